// Framer for one VN-300 serial port: a byte stream that mixes binary packets (0xFA), split
// binary packets (0xFB) and ASCII sentences ('$' ... '\n'), as a real port can (ICD L115, L135).
//
// Bytes arrive in chunks of any size. At each sync candidate the framer decides: a complete,
// checksum-valid frame (handed to the callback), a candidate that needs more bytes (kept for the
// next chunk; at most one maximum-size frame is ever buffered), or not a frame. On a failed
// candidate the search restarts one byte after its first byte, so a frame hidden inside a
// corrupted one is still found. Only candidates whose structure parsed and whose checksum failed
// count as bad frames; a stray sync byte in noise counts as skipped bytes only.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/vectornav/binary_header.hpp"
#include "frontends/vectornav/split_packet.hpp"

namespace navfuse::frontends::vectornav {

enum class FrameKind : std::uint8_t { kBinary, kSplit, kAscii };

// Longest ASCII sentence accepted. The longest VN-300 output (Reg 72/73 state, ~170 characters)
// fits with room; the input buffer of the device itself is 256 characters (ICD L653).
inline constexpr std::size_t kMaxAsciiSentenceBytes = 512;

struct Frame {
  FrameKind kind = FrameKind::kBinary;
  std::span<const std::uint8_t> bytes;  // the whole frame, sync to CRC / '$' to '\n'
  std::uint64_t offset = 0;             // stream offset of bytes[0]
  const BinaryHeader* header = nullptr;           // kBinary: the parsed header
  const SplitPacketHeader* split = nullptr;       // kSplit: the parsed split header
};

class PortFramer {
 public:
  PortFramer() { buffer_.reserve(kBufferReserve); }

  // Frames `bytes`, calling on_frame(const Frame&) for each valid frame in stream order.
  template <class OnFrame>
  void feed(std::span<const std::uint8_t> bytes, OnFrame&& on_frame);
  // End of stream: candidates still waiting for bytes are given up (search resumes one byte
  // after each), and whatever cannot be framed is counted as skipped.
  template <class OnFrame>
  void finish(OnFrame&& on_frame);

  StreamCounters& counters() { return counters_; }
  const StreamCounters& counters() const { return counters_; }
  std::uint64_t framed_bytes() const { return framed_bytes_; }
  std::size_t buffered_bytes() const { return buffer_.size(); }

 private:
  enum class Verdict : std::uint8_t { kFrame, kIncomplete, kBad, kNotFrame };
  struct Attempt {
    Verdict verdict = Verdict::kNotFrame;
    std::size_t length = 0;
  };
  static constexpr std::size_t kBufferReserve = 1u << 16;

  Attempt try_binary(const std::uint8_t* p, std::size_t n);
  Attempt try_split(const std::uint8_t* p, std::size_t n);
  static Attempt try_ascii(const std::uint8_t* p, std::size_t n);

  template <class OnFrame>
  std::size_t scan(const std::uint8_t* data, std::size_t n, bool final, OnFrame& on_frame);

  StreamCounters counters_;
  std::uint64_t framed_bytes_ = 0;
  std::uint64_t base_offset_ = 0;  // stream offset of buffer_[0] (or of the chunk being scanned)
  std::vector<std::uint8_t> buffer_;
  BinaryHeader header_;
  SplitPacketHeader split_;
};

// Table of bytes that can start a frame.
struct SyncTable {
  std::array<bool, 256> is_sync{};
  constexpr SyncTable() {
    is_sync[0xFA] = true;
    is_sync[0xFB] = true;
    is_sync[static_cast<unsigned char>('$')] = true;
  }
};
inline constexpr SyncTable kSyncTable{};

template <class OnFrame>
std::size_t PortFramer::scan(const std::uint8_t* data, std::size_t n, bool final, OnFrame& on_frame) {
  std::size_t i = 0;
  while (i < n) {
    std::size_t j = i;
    while (j < n && !kSyncTable.is_sync[data[j]]) ++j;
    counters_.skipped_bytes += j - i;
    i = j;
    if (i == n) break;
    Attempt a;
    FrameKind kind;
    if (data[i] == kSyncBinary) {
      a = try_binary(data + i, n - i);
      kind = FrameKind::kBinary;
    } else if (data[i] == kSyncSplit) {
      a = try_split(data + i, n - i);
      kind = FrameKind::kSplit;
    } else {
      a = try_ascii(data + i, n - i);
      kind = FrameKind::kAscii;
    }
    switch (a.verdict) {
      case Verdict::kFrame: {
        Frame f;
        f.kind = kind;
        f.bytes = {data + i, a.length};
        f.offset = base_offset_ + i;
        f.header = &header_;
        f.split = &split_;
        ++counters_.frames;
        framed_bytes_ += a.length;
        i += a.length;
        on_frame(static_cast<const Frame&>(f));
        break;
      }
      case Verdict::kIncomplete:
        if (!final) return i;
        ++counters_.skipped_bytes;
        ++i;
        break;
      case Verdict::kBad:
        ++counters_.bad_frames;
        ++counters_.skipped_bytes;
        ++i;
        break;
      case Verdict::kNotFrame:
        ++counters_.skipped_bytes;
        ++i;
        break;
    }
  }
  return i;
}

template <class OnFrame>
void PortFramer::feed(std::span<const std::uint8_t> bytes, OnFrame&& on_frame) {
  counters_.bytes += bytes.size();
  if (buffer_.empty()) {
    // Fast path: frame straight from the caller's chunk, keep only an incomplete tail.
    const std::size_t used = scan(bytes.data(), bytes.size(), false, on_frame);
    base_offset_ += used;
    buffer_.assign(bytes.begin() + static_cast<std::ptrdiff_t>(used), bytes.end());
    return;
  }
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  const std::size_t used = scan(buffer_.data(), buffer_.size(), false, on_frame);
  base_offset_ += used;
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(used));
}

template <class OnFrame>
void PortFramer::finish(OnFrame&& on_frame) {
  const std::size_t used = scan(buffer_.data(), buffer_.size(), true, on_frame);
  base_offset_ += used;
  buffer_.clear();
}

}  // namespace navfuse::frontends::vectornav

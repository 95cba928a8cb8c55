// Framer for NMEA-0183-style ASCII sentences, `$BODY*HH\r\n`, as NMEA receivers and the Unicore
// UM220-INS protocol write them (Unicore INS protocol spec R2.8 §1-§2, L130-L172; digest §1).
//
// Bytes arrive in chunks of any size. A complete sentence found inside one chunk is validated in
// place (no copy); only a sentence split across chunks is copied into a fixed buffer, so the
// framer never allocates. Garbage, control bytes, over-long lines, a '$' inside a sentence and
// wrong checksums make the framer count and resynchronise on the next start character.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends::nmea {

// "The total length of each message does not exceed 128 bytes" (Unicore spec L152), counted
// here from the start character through the "\r\n" terminator.
inline constexpr std::size_t kUnicoreMaxSentenceBytes = 128;
inline constexpr std::size_t kTerminatorBytes = 2;  // "\r\n" (L152)
inline constexpr std::size_t kChecksumFieldBytes = 3;  // '*' and two hex digits (L164)

struct FramerOptions {
  // Longest sentence accepted, start character and "\r\n" included.
  std::size_t max_sentence_bytes = kUnicoreMaxSentenceBytes;
  // The Unicore spec makes the checksum optional on input (L166) and its output examples often
  // omit it (digest §11 item 3), so by default a sentence without "*HH" is accepted. A present
  // but wrong checksum is always rejected.
  bool require_checksum = false;
  // Also frame lines starting with '#': the UM220 command echo "#<user command>" (L250-L260).
  bool accept_hash_start = true;
};

// One validated sentence. Views point into the caller's chunk or the framer's buffer and are
// valid only during the callback.
struct Frame {
  std::string_view body;      // text between the start character and '*' (or the terminator)
  char start = '$';           // '$' or '#'
  bool has_checksum = false;  // "*HH" was present (and matched)
  std::uint64_t offset = 0;   // stream offset of the start character
};

class SentenceFramer {
 public:
  explicit SentenceFramer(FramerOptions options = {});

  // Feeds a chunk; calls on_frame(const Frame&) for every valid sentence, in stream order.
  template <class OnFrame>
  void feed(std::span<const std::uint8_t> bytes, OnFrame&& on_frame);

  // End of stream: a partial trailing sentence is counted as skipped bytes.
  void finish();

  const frontends::StreamCounters& counters() const { return counters_; }
  // The decoder above adds unknown_frames / decode_errors to the same counters.
  frontends::StreamCounters& counters() { return counters_; }

 private:
  // Byte classes of the scanner: one table lookup per byte decides whether the scan stops.
  enum ByteClass : std::uint8_t { kText = 0, kTerminator = 1, kStart = 2, kInvalid = 3 };
  static const std::array<std::uint8_t, 256> kByteClass;

  // Checks a complete sentence text (start character up to, excluding, the terminator) and
  // delivers it. `xor_all` is the XOR of every byte after the start character. On success the
  // terminator (and a '\n' after '\r') belongs to the frame; on failure it is skipped too.
  template <class OnFrame>
  void deliver_terminated(const std::uint8_t* text, std::size_t size, std::uint8_t terminator,
                          std::uint8_t xor_all, std::uint64_t offset, OnFrame& on_frame);
  // Result of checking a sentence text; body_size is the length of the body on success.
  bool check(const std::uint8_t* text, std::size_t size, std::uint8_t xor_all,
             std::size_t& body_size, bool& has_checksum) const;

  const std::uint8_t* find_start(const std::uint8_t* p, const std::uint8_t* end) const;

  FramerOptions options_;
  std::size_t max_text_ = 0;  // longest text before the terminator
  frontends::StreamCounters counters_;
  // Partial sentence carried over from the previous chunk.
  std::array<std::uint8_t, 1024> partial_{};
  std::size_t partial_size_ = 0;
  std::uint8_t partial_xor_ = 0;
  std::uint64_t partial_offset_ = 0;
  bool swallow_lf_ = false;  // the last sentence ended with '\r': its '\n' belongs to it
};

// ---------------------------------------------------------------------------------------------
// Template implementation (the scanner is the hot loop; keep it inline in the caller).

template <class OnFrame>
void SentenceFramer::deliver_terminated(const std::uint8_t* text, std::size_t size,
                                        std::uint8_t terminator, std::uint8_t xor_all,
                                        std::uint64_t offset, OnFrame& on_frame) {
  std::size_t body_size = 0;
  bool has_checksum = false;
  if (!check(text, size, xor_all, body_size, has_checksum)) {
    ++counters_.bad_frames;
    counters_.skipped_bytes += size + 1;
    swallow_lf_ = false;
    return;
  }
  swallow_lf_ = terminator == '\r';
  ++counters_.frames;
  Frame frame;
  frame.body = std::string_view(reinterpret_cast<const char*>(text) + 1, body_size);
  frame.start = static_cast<char>(text[0]);
  frame.has_checksum = has_checksum;
  frame.offset = offset;
  on_frame(static_cast<const Frame&>(frame));
}

template <class OnFrame>
void SentenceFramer::feed(std::span<const std::uint8_t> bytes, OnFrame&& on_frame) {
  const std::uint8_t* const begin = bytes.data();
  const std::uint8_t* const end = begin + bytes.size();
  const std::uint64_t base = counters_.bytes;  // stream offset of `begin`
  counters_.bytes += bytes.size();
  const std::uint8_t* p = begin;

  if (partial_size_ > 0) {
    // Continue the sentence left over from the previous chunk.
    std::size_t i = 0;
    const std::size_t room = max_text_ + 1 - partial_size_;
    const std::size_t limit = std::min<std::size_t>(static_cast<std::size_t>(end - p), room);
    std::uint8_t x = partial_xor_;
    while (i < limit && kByteClass[p[i]] == kText) x ^= p[i++];
    std::copy(p, p + i, partial_.begin() + static_cast<std::ptrdiff_t>(partial_size_));
    if (i == static_cast<std::size_t>(end - p) && i < room) {  // still incomplete
      partial_size_ += i;
      partial_xor_ = x;
      return;
    }
    const std::size_t size = partial_size_ + i;
    partial_size_ = 0;
    if (i < limit && kByteClass[p[i]] == kTerminator) {
      deliver_terminated(partial_.data(), size, p[i], x, partial_offset_, on_frame);
      p += i + 1;
    } else {  // too long, a control byte, or a new start character inside the sentence
      ++counters_.bad_frames;
      counters_.skipped_bytes += size;
      p += i;
    }
  }

  while (p < end) {
    if (swallow_lf_) {
      swallow_lf_ = false;
      if (*p == '\n') {
        ++p;
        continue;
      }
    }
    const std::uint8_t* start = find_start(p, end);
    counters_.skipped_bytes += static_cast<std::uint64_t>(start - p);
    if (start == end) return;
    const std::size_t avail = static_cast<std::size_t>(end - start);
    const std::size_t limit = std::min(avail, max_text_ + 1);
    std::size_t i = 1;
    std::uint8_t x = 0;
    while (i < limit && kByteClass[start[i]] == kText) x ^= start[i++];
    const std::uint64_t offset = base + static_cast<std::uint64_t>(start - begin);
    if (i == avail && i <= max_text_) {  // runs past the chunk: keep it for the next one
      std::copy(start, end, partial_.begin());
      partial_size_ = avail;
      partial_xor_ = x;
      partial_offset_ = offset;
      return;
    }
    if (i < limit && kByteClass[start[i]] == kTerminator) {
      deliver_terminated(start, i, start[i], x, offset, on_frame);
      p = start + i + 1;
    } else {
      ++counters_.bad_frames;
      counters_.skipped_bytes += i;
      p = start + i;
    }
  }
}

}  // namespace navfuse::frontends::nmea

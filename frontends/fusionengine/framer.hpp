// FusionEngine framer: bytes in arbitrary chunks -> CRC-validated frames.
//
// Procedure (digest §1.5, from spec §2.3-2.4 L179-229):
//   1. memchr for sync byte 0 (0x2E), then check sync byte 1 (0x31);
//   2. read the 24-byte header; reserved bytes 2-3 must be 0 (every spec example, and the public
//      client's framer, drop a candidate otherwise) and payload_size must not exceed what the
//      type can hold (max_payload_size(), message_catalog.hpp): the largest payload the type's
//      layout can express plus kMaxVersionGrowth, kMaxUnknownPayloadSize for a type not in the
//      catalogue; all before any CRC, so a corrupted size costs no wait and no CRC beyond that;
//   3. CRC-32 over [8, 24 + payload_size) must equal the header CRC;
//   4. on any failure restart the sync search one byte after the candidate's first byte.
// Payload sizes need not be multiples of 4 (spec L153 vs example L891-895, digest §13 A1).
//
// Frames are delivered through a template callback (no std::function or virtual call per frame).
// When a chunk holds whole frames they are framed in place; only a trailing partial frame is
// copied into an internal buffer whose capacity is reused, so steady-state framing does not
// allocate. The spans given to the callback are valid only during the call.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "core/bytes/byte_reader.hpp"
#include "core/bytes/checks.hpp"
#include "frontends/common/stream_decoder.hpp"
#include "frontends/fusionengine/message_catalog.hpp"
#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

struct Frame {
  Header header;
  std::span<const std::uint8_t> payload;
  std::span<const std::uint8_t> bytes;  // header + payload
  std::uint64_t offset = 0;             // of the first sync byte in the stream
};

// Parses the 24 header bytes at `p` (caller guarantees 24 bytes).
inline Header parse_header(const std::uint8_t* p) {
  bytes::LeReader r({p + kCrcOffset, kHeaderSize - kCrcOffset});
  Header h;
  h.crc = r.u32();
  h.protocol_version = r.u8();
  h.message_version = r.u8();
  h.message_type = r.u16();
  h.sequence = r.u32();
  h.payload_size = r.u32();
  h.source_id = r.u32();
  return h;
}

class Framer {
 public:
  // Feeds the next chunk; calls on_frame(const Frame&) for every valid frame completed.
  template <class OnFrame>
  void feed(std::span<const std::uint8_t> data, OnFrame&& on_frame) {
    counters_.bytes += data.size();
    if (pending_.empty()) {
      const std::size_t used = scan(data.data(), data.size(), stream_offset_, on_frame, false);
      pending_.assign(data.begin() + static_cast<std::ptrdiff_t>(used), data.end());
      pending_offset_ = stream_offset_ + used;
    } else {
      pending_.insert(pending_.end(), data.begin(), data.end());
      consume_pending(on_frame, false);
    }
    stream_offset_ += data.size();
  }

  // End of stream. A candidate frame still incomplete is not a frame: it is dropped one byte at
  // a time and the rest rescanned, so that a corrupted length near the end of a stream cannot
  // hide the valid frames behind it. Whatever remains unframed is counted as skipped.
  template <class OnFrame>
  void finish(OnFrame&& on_frame) {
    consume_pending(on_frame, true);
  }

  const frontends::StreamCounters& counters() const { return counters_; }
  frontends::StreamCounters& counters() { return counters_; }
  // Bytes that ended up inside valid frames (for the invariant bytes = framed + skipped +
  // buffered that fuzz targets check).
  std::uint64_t framed_bytes() const { return framed_bytes_; }
  std::size_t buffered_bytes() const { return pending_.size(); }

 private:
  template <class OnFrame>
  void consume_pending(OnFrame& on_frame, bool final) {
    const std::size_t used = scan(pending_.data(), pending_.size(), pending_offset_, on_frame, final);
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(used));
    pending_offset_ += used;
  }

  // Frames what it can of [p, p + n); returns the bytes consumed (framed or skipped). With
  // `final`, an incomplete candidate is skipped instead of waited for.
  template <class OnFrame>
  std::size_t scan(const std::uint8_t* p, std::size_t n, std::uint64_t base_offset,
                   OnFrame& on_frame, bool final) {
    std::size_t pos = 0;
    while (pos < n) {
      const void* hit = std::memchr(p + pos, kSync0, n - pos);
      if (hit == nullptr) {
        counters_.skipped_bytes += n - pos;
        return n;
      }
      const std::size_t start = static_cast<std::size_t>(static_cast<const std::uint8_t*>(hit) - p);
      counters_.skipped_bytes += start - pos;
      pos = start;
      const std::size_t avail = n - pos;
      if (avail >= 2 && p[pos + 1] != kSync1) {
        ++counters_.skipped_bytes;
        ++pos;
        continue;
      }
      if (avail < kHeaderSize) {
        if (!final) return pos;
        ++counters_.skipped_bytes;
        ++pos;
        continue;
      }
      if (p[pos + 2] != 0 || p[pos + 3] != 0) {  // reserved bytes: not a header
        ++counters_.skipped_bytes;
        ++pos;
        continue;
      }
      const Header h = parse_header(p + pos);
      if (h.payload_size > max_payload_size(h.message_type)) {
        ++counters_.bad_frames;
        ++counters_.skipped_bytes;
        ++pos;
        continue;
      }
      const std::size_t total = kHeaderSize + h.payload_size;
      if (avail < total) {
        if (!final) return pos;
        ++counters_.skipped_bytes;
        ++pos;
        continue;
      }
      const std::uint32_t crc =
          bytes::crc32({p + pos + kCrcCoveredFrom, total - kCrcCoveredFrom});
      if (crc != h.crc) {
        ++counters_.bad_frames;
        ++counters_.skipped_bytes;
        ++pos;
        continue;
      }
      ++counters_.frames;
      framed_bytes_ += total;
      Frame f{h, {p + pos + kHeaderSize, h.payload_size}, {p + pos, total}, base_offset + pos};
      pos += total;
      on_frame(static_cast<const Frame&>(f));
    }
    return pos;
  }

  frontends::StreamCounters counters_;
  std::vector<std::uint8_t> pending_;
  std::uint64_t pending_offset_ = 0;
  std::uint64_t stream_offset_ = 0;
  std::uint64_t framed_bytes_ = 0;
};

}  // namespace navfuse::frontends::fusionengine

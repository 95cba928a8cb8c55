// MIP framer: bytes in arbitrary chunks -> validated packets (digest §2, spec L3814-4089).
//
// Validation per packet: sync "ue", payload length, Fletcher checksum (§2.3) and the field walk
// (a field LEN < 2 or past the payload end invalidates the packet, §2.2). After garbage or a
// failed packet the sync search restarts one byte after the failed packet's first byte (§2.9,
// L4042). Nothing is allocated per packet: packets wholly inside a fed chunk are handed out in
// place; only a packet split across chunks is assembled in a fixed carry buffer.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/mip/checksum.hpp"
#include "frontends/mip/packet.hpp"
#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {

class Framer {
 public:
  // Feeds the next chunk; calls on_packet(const PacketView&) for every valid packet, in order.
  template <class OnPacket>
  void feed(std::span<const std::uint8_t> data, OnPacket&& on_packet);
  // End of stream. A packet still waiting for bytes can no longer complete: like the spec's
  // receive timeout (§2.9, L4036-4042) its start is dropped and the held bytes are searched
  // again from the next byte, so a valid packet inside them is still delivered; the rest is
  // counted as skipped.
  template <class OnPacket>
  void finish(OnPacket&& on_packet);
  const StreamCounters& counters() const { return counters_; }
  StreamCounters& counters() { return counters_; }
  // Bytes held back waiting for the rest of a packet (counters: bytes = framed + skipped + this).
  std::size_t buffered() const { return carry_len_; }

  // Checksum and field walk of one complete packet candidate (sync and length already read).
  static bool packet_valid(const std::uint8_t* p, std::size_t total) {
    const std::size_t body = total - kChecksumSize;
    const std::uint16_t expected =
        static_cast<std::uint16_t>((p[body] << 8) | p[body + 1]);  // MSB first (L3821)
    if (fletcher_fast(p, body) != expected) return false;
    return fields_well_formed(std::span<const std::uint8_t>(p + kHeaderSize, body - kHeaderSize));
  }

 private:
  // Scans buf[0, len) for packets whose first byte lies before start_limit. Returns where the
  // scan stopped: start_limit, or the start of a packet that needs bytes beyond len.
  template <class OnPacket>
  std::size_t scan(const std::uint8_t* buf, std::size_t len, std::size_t start_limit,
                   std::uint64_t base_offset, OnPacket& on_packet);

  // A packet that starts in the carry is at most kMaxPacket long, so carry + kMaxPacket bytes of
  // the next chunk always complete it.
  static constexpr std::size_t kCarryCapacity = 2 * kMaxPacket;
  std::array<std::uint8_t, kCarryCapacity> carry_{};
  std::size_t carry_len_ = 0;
  std::uint64_t carry_offset_ = 0;  // stream offset of carry_[0]
  std::uint64_t stream_pos_ = 0;    // stream offset of the next byte to be fed
  StreamCounters counters_{};
};

template <class OnPacket>
std::size_t Framer::scan(const std::uint8_t* buf, std::size_t len, std::size_t start_limit,
                         std::uint64_t base_offset, OnPacket& on_packet) {
  std::size_t pos = 0;
  while (pos < start_limit) {
    if (buf[pos] != kSync1) {
      const void* hit = std::memchr(buf + pos, kSync1, start_limit - pos);
      const std::size_t next =
          hit ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(hit) - buf) : start_limit;
      counters_.skipped_bytes += next - pos;
      pos = next;
      continue;
    }
    if (pos + 1 >= len) break;
    if (buf[pos + 1] != kSync2) {
      ++counters_.skipped_bytes;
      ++pos;
      continue;
    }
    if (pos + kHeaderSize > len) break;
    const std::size_t total = static_cast<std::size_t>(buf[pos + kLengthOffset]) + kWrapperSize;
    if (total > len - pos) break;
    if (packet_valid(buf + pos, total)) {
      ++counters_.frames;
      PacketView view;
      view.desc_set = buf[pos + kSetOffset];
      view.bytes = std::span<const std::uint8_t>(buf + pos, total);
      view.payload = view.bytes.subspan(kHeaderSize, total - kWrapperSize);
      view.offset = base_offset + pos;
      on_packet(view);
      pos += total;
    } else {
      ++counters_.bad_frames;
      ++counters_.skipped_bytes;
      ++pos;  // L4042: restart the search at the byte after the false "ue"
    }
  }
  return pos;
}

template <class OnPacket>
void Framer::finish(OnPacket&& on_packet) {
  std::size_t pos = 0;
  while (pos < carry_len_) {
    pos += scan(carry_.data() + pos, carry_len_ - pos, carry_len_ - pos, carry_offset_ + pos, on_packet);
    if (pos < carry_len_) {
      ++counters_.skipped_bytes;  // the start of the packet that never completed
      ++pos;
    }
  }
  carry_len_ = 0;
}

template <class OnPacket>
void Framer::feed(std::span<const std::uint8_t> data, OnPacket&& on_packet) {
  counters_.bytes += data.size();
  const std::uint64_t chunk_offset = stream_pos_;
  stream_pos_ += data.size();
  std::size_t data_pos = 0;
  if (carry_len_ > 0) {
    const std::size_t old_len = carry_len_;
    const std::size_t take = std::min(data.size(), kCarryCapacity - old_len);
    std::memcpy(carry_.data() + old_len, data.data(), take);
    const std::size_t len = old_len + take;
    const std::size_t stop = scan(carry_.data(), len, old_len, carry_offset_, on_packet);
    if (stop < old_len) {
      // Still incomplete: everything fed so far sits in the carry (take == data.size() here).
      std::memmove(carry_.data(), carry_.data() + stop, len - stop);
      carry_len_ = len - stop;
      carry_offset_ += stop;
      return;
    }
    carry_len_ = 0;
    data_pos = stop - old_len;
  }
  const std::size_t rest = data.size() - data_pos;
  if (rest == 0) return;
  const std::uint8_t* base = data.data() + data_pos;
  const std::size_t stop = scan(base, rest, rest, chunk_offset + data_pos, on_packet);
  carry_len_ = rest - stop;  // < kMaxPacket: only an incomplete packet stops the scan early
  std::memcpy(carry_.data(), base + stop, carry_len_);
  carry_offset_ = chunk_offset + data_pos + stop;
}

}  // namespace navfuse::frontends::mip

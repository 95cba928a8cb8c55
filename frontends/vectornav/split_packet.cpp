#include "frontends/vectornav/split_packet.hpp"

#include "core/bytes/checks.hpp"

namespace navfuse::frontends::vectornav {
namespace {
constexpr unsigned kNibbleBits = 4;
constexpr std::uint8_t kNibbleMask = 0x0F;
}  // namespace

ParseStatus parse_split_header(std::span<const std::uint8_t> bytes, SplitPacketHeader& out) {
  if (bytes.size() < kSplitHeaderBytes) return ParseStatus::kIncomplete;
  if (bytes[0] != kSplitMsgType) return ParseStatus::kInvalid;
  out.message_id = bytes[1];
  out.total = static_cast<std::uint8_t>(bytes[2] >> kNibbleBits);
  out.index = static_cast<std::uint8_t>(bytes[2] & kNibbleMask);
  out.payload_bytes = static_cast<std::uint16_t>(bytes[3] | (bytes[4] << 8));
  if (out.total == 0 || out.index > out.total || out.payload_bytes == 0 ||
      out.payload_bytes > kMaxSplitPayloadBytes)
    return ParseStatus::kInvalid;
  return ParseStatus::kOk;
}

SplitReassembler::Result SplitReassembler::add(const SplitPacketHeader& h, std::span<const std::uint8_t> payload) {
  bool abandoned = false;
  if (in_flight_ && (h.message_id != message_id_ || h.total != total_ || h.index != next_)) {
    in_flight_ = false;
    abandoned = true;
    has_orphan_ = true;
    orphan_id_ = message_id_;
  }
  if (!in_flight_) {
    // A message may start at index 0 or 1 (errata A25: the nibble base is not stated); a later
    // index is the continuation of a message whose start was lost.
    if (h.index > 1) {
      packets_ = 0;
      if (abandoned) return Result::kAbandoned;
      if (has_orphan_ && h.message_id == orphan_id_) return Result::kIgnored;
      has_orphan_ = true;
      orphan_id_ = h.message_id;
      return Result::kAbandoned;
    }
    body_.clear();
    packets_ = 0;
    in_flight_ = true;
    has_orphan_ = false;
    message_id_ = h.message_id;
    total_ = h.total;
    base_ = h.index;
    next_ = h.index;
  }
  body_.insert(body_.end(), payload.begin(), payload.end());
  ++next_;
  ++packets_;
  if (static_cast<unsigned>(next_ - base_) == total_) {
    in_flight_ = false;
    return Result::kComplete;
  }
  return abandoned ? Result::kAbandoned : Result::kPending;
}

bool SplitReassembler::abandon() {
  const bool was = in_flight_;
  in_flight_ = false;
  return was;
}

bool append_split_packets(std::span<const std::uint8_t> body, std::uint8_t message_id,
                          std::vector<std::uint8_t>& out) {
  const std::size_t packets = (body.size() + kMaxSplitPayloadBytes - 1) / kMaxSplitPayloadBytes;
  if (packets == 0 || packets > kMaxSplitPackets) return false;
  for (std::size_t k = 0; k < packets; ++k) {
    const std::span<const std::uint8_t> chunk =
        body.subspan(k * kMaxSplitPayloadBytes, std::min(kMaxSplitPayloadBytes, body.size() - k * kMaxSplitPayloadBytes));
    out.push_back(kSyncSplit);
    const std::size_t start = out.size();
    out.push_back(kSplitMsgType);
    out.push_back(message_id);
    out.push_back(static_cast<std::uint8_t>((packets << kNibbleBits) | (k + 1)));
    out.push_back(static_cast<std::uint8_t>(chunk.size() & 0xFFu));
    out.push_back(static_cast<std::uint8_t>(chunk.size() >> 8));
    out.insert(out.end(), chunk.begin(), chunk.end());
    // Same CRC as a standard packet: over header and payload, sync excluded, big-endian (L5406).
    const std::uint16_t crc = bytes::crc16_xmodem(std::span<const std::uint8_t>(out).subspan(start));
    out.push_back(static_cast<std::uint8_t>(crc >> 8));
    out.push_back(static_cast<std::uint8_t>(crc & 0xFFu));
  }
  return true;
}

}  // namespace navfuse::frontends::vectornav

// Split binary packets (sync 0xFB; ICD Appendix B.1.2, L5395-5416; digest §4.6): messages over
// 600 bytes go out as up to 15 packets whose payloads concatenate to the header and payload of
// one standard message (no 0xFA sync, no CRC).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "frontends/vectornav/binary_header.hpp"

namespace navfuse::frontends::vectornav {

// Table B.1: MsgType, MessageID, PacketCount (high nibble total, low nibble index), PayloadLength.
inline constexpr std::size_t kSplitHeaderBytes = 5;
inline constexpr std::uint8_t kSplitMsgType = 0x00;
inline constexpr std::size_t kMaxSplitPackets = 15;  // one nibble
inline constexpr std::size_t kMaxSplitPayloadBytes = kMaxBinaryPacketBytes - 1 - kSplitHeaderBytes - kCrcBytes;

struct SplitPacketHeader {
  std::uint8_t message_id = 0;
  std::uint8_t total = 0;  // packets in the message
  std::uint8_t index = 0;  // this packet's number (errata A25: base 0 or 1, both accepted)
  std::uint16_t payload_bytes = 0;
};

// Parses the 5-byte header that follows the 0xFB sync. Errata A25 (digest §10, L5406-5416):
// PayloadLength is read little-endian like every other multi-byte binary value.
ParseStatus parse_split_header(std::span<const std::uint8_t> bytes, SplitPacketHeader& out);

// Reassembles split packets into a message body. Keeps one message in flight; a packet out of
// sequence abandons it (the caller counts that as a decode error).
class SplitReassembler {
 public:
  // kAbandoned is returned once per lost message; later packets of it give kIgnored.
  enum class Result : std::uint8_t { kPending, kComplete, kAbandoned, kIgnored };
  SplitReassembler() { body_.reserve(kMaxSplitPackets * kMaxSplitPayloadBytes); }
  // `payload` is the packet's payload. On kComplete, body() holds the reassembled message.
  // kAbandoned means a partial message was dropped (this packet may have started a new one).
  Result add(const SplitPacketHeader& header, std::span<const std::uint8_t> payload);
  std::span<const std::uint8_t> body() const { return body_; }
  // Packets in the message being (or just) assembled: 1 right after its first packet.
  std::size_t packets() const { return packets_; }
  // Drops a message in flight (end of stream); true if there was one.
  bool abandon();

 private:
  std::vector<std::uint8_t> body_;
  std::size_t packets_ = 0;
  bool in_flight_ = false;
  bool has_orphan_ = false;  // a message already counted as lost, whose packets are ignored
  std::uint8_t orphan_id_ = 0;
  std::uint8_t message_id_ = 0, total_ = 0, base_ = 0, next_ = 0;
};

// Appends `body` (header + payload of a standard message) as split packets, numbered from 1
// (the "current packet count" reading of Table B.1). Returns false if it needs more than 15.
bool append_split_packets(std::span<const std::uint8_t> body, std::uint8_t message_id,
                          std::vector<std::uint8_t>& out);

}  // namespace navfuse::frontends::vectornav

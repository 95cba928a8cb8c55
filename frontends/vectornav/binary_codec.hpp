// Whole binary messages: the body (header + payload, between the sync byte and the CRC) to a
// BinaryMessage and back, the packet wrapping (sync, big-endian CRC16, split packets when over
// 600 bytes) and the FrameRecord listing.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/vectornav/binary_message.hpp"

namespace navfuse::frontends::vectornav {

// Decodes a message body into `msg` (fields not in the header keep stale values; check
// msg.has()). False when the header is invalid or the payload length disagrees with it.
bool decode_binary_body(std::span<const std::uint8_t> body, BinaryMessage& msg);

// Appends `msg` as one 0xFA packet, or as 0xFB split packets (ICD L5397) when the packet would
// exceed 600 bytes. Returns false (appending nothing) if the message cannot be represented:
// no types, a list longer than 255 entries, or more than 15 split packets.
bool append_binary_message(BinaryMessage& msg, std::vector<std::uint8_t>& out, std::uint8_t split_message_id = 0);

// Lists every field of `msg` (names carry units and the group, e.g. "ins.lat_deg").
void describe_binary_message(BinaryMessage& msg, FrameRecord& record);

}  // namespace navfuse::frontends::vectornav

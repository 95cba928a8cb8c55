#include "frontends/vectornav/binary_codec.hpp"

#include <limits>

#include "core/bytes/checks.hpp"
#include "frontends/vectornav/field_io.hpp"
#include "frontends/vectornav/message_visit.hpp"
#include "frontends/vectornav/split_packet.hpp"

namespace navfuse::frontends::vectornav {

bool decode_binary_body(std::span<const std::uint8_t> body, BinaryMessage& msg) {
  if (parse_header(body, msg.header) != ParseStatus::kOk) return false;
  const auto payload = body.subspan(msg.header.header_bytes);
  std::size_t expected = 0;
  if (measure_payload(msg.header, payload, payload.size(), expected) != ParseStatus::kOk ||
      expected != payload.size())
    return false;
  bytes::LeReader r(payload);
  FieldReader io(r);
  visit_message(io, msg);
  return r.ok() && r.remaining() == 0;
}

bool append_binary_message(BinaryMessage& msg, std::vector<std::uint8_t>& out, std::uint8_t split_message_id) {
  if (msg.header.groups == 0) return false;
  for (const GnssFields& g : msg.gnss)
    if (g.sat_info.size() > std::numeric_limits<std::uint8_t>::max() ||
        g.raw_meas.size() > std::numeric_limits<std::uint8_t>::max())
      return false;
  const std::size_t start = out.size();
  out.push_back(kSyncBinary);
  append_header(msg.header, out);
  msg.header.header_bytes = out.size() - start - 1;
  bytes::LeWriter w(out);
  FieldWriter io(w);
  visit_message(io, msg);
  if (out.size() - start + kCrcBytes <= kMaxBinaryPacketBytes) {
    // CRC over header + payload, sync excluded, appended big-endian (L699, errata A3).
    const std::uint16_t crc = bytes::crc16_xmodem(std::span<const std::uint8_t>(out).subspan(start + 1));
    out.push_back(static_cast<std::uint8_t>(crc >> 8));
    out.push_back(static_cast<std::uint8_t>(crc & 0xFFu));
    return true;
  }
  const std::vector<std::uint8_t> body(out.begin() + static_cast<std::ptrdiff_t>(start + 1), out.end());
  out.resize(start);
  if (!append_split_packets(body, split_message_id, out)) {
    out.resize(start);
    return false;
  }
  return true;
}

void describe_binary_message(BinaryMessage& msg, FrameRecord& record) {
  FieldDescriber io(record, "");
  visit_message(io, msg);
}

}  // namespace navfuse::frontends::vectornav

#include "frontends/fusionengine/writer.hpp"


#include "core/bytes/byte_writer.hpp"
#include "core/bytes/checks.hpp"

namespace navfuse::frontends::fusionengine {

std::uint32_t default_source_id(std::uint16_t message_type) {
  switch (static_cast<MessageType>(message_type)) {
    case MessageType::kImuInput:
    case MessageType::kWheelTickInput:
    case MessageType::kVehicleTickInput:
    case MessageType::kWheelSpeedInput:
    case MessageType::kVehicleSpeedInput:
      return kSourceIdMeasurementInput;
    default:
      return kSourceIdInvalid;
  }
}

std::size_t begin_frame(std::vector<std::uint8_t>& out, std::uint16_t message_type, std::uint8_t message_version,
                        std::uint32_t sequence, std::uint32_t source_id, std::size_t payload_bytes) {
  // The header grows the buffer once (reserved, CRC and payload size stay zero until
  // end_frame()) and its fields are patched in: one append per frame instead of one per field,
  // which a pose output per IMU sample pays three times.
  const std::size_t start = out.size();
  out.resize(start + kHeaderSize + payload_bytes);
  bytes::LeWriter w(out);
  w.patch(start, kSync0);
  w.patch(start + 1, kSync1);
  w.patch(start + kProtocolVersionOffset, kProtocolVersion);
  w.patch(start + kMessageVersionOffset, message_version);
  w.patch(start + kMessageTypeOffset, message_type);
  w.patch(start + kSequenceOffset, sequence);
  w.patch(start + kSourceIdOffset, source_id);
  return start;
}

void end_frame(std::vector<std::uint8_t>& out, std::size_t start) {
  bytes::LeWriter w(out);
  w.patch(start + kPayloadSizeOffset, static_cast<std::uint32_t>(out.size() - start - kHeaderSize));
  // The CRC covers bytes [8, end), not the CRC field itself (spec L186).
  w.patch(start + kCrcOffset,
          bytes::crc32({out.data() + start + kCrcCoveredFrom, out.size() - start - kCrcCoveredFrom}));
}

const std::vector<std::uint8_t>& FusionEngineWriter::imu_output(const ImuSample& imu) {
  ImuOutputMessage m;
  if (!imu_output_from(imu, m)) {
    buffer_.clear();
    return buffer_;
  }
  return frame(m);
}

}  // namespace navfuse::frontends::fusionengine

#include "frontends/mip/responder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/bytes/byte_reader.hpp"
#include "core/bytes/checks.hpp"
#include "frontends/mip/field_schema.hpp"
#include "frontends/mip/packet.hpp"
#include "frontends/mip/sensor_to_vehicle.hpp"
#include "frontends/mip/writer.hpp"

namespace navfuse::frontends::mip {
namespace {

// (set, command) -> response descriptor (digest §7.7).
struct ResponseMap {
  std::uint8_t set, cmd, resp;
};
constexpr ResponseMap kResponses[] = {
    {0x01, 0x03, 0x81}, {0x01, 0x04, 0x82}, {0x01, 0x05, 0x83}, {0x01, 0x07, 0x86}, {0x01, 0x08, 0x88},
    {0x01, 0x09, 0x89}, {0x0C, 0x0C, 0x8C}, {0x0C, 0x0E, 0x8E}, {0x0C, 0x0F, 0x8F}, {0x0C, 0x11, 0x85},
    {0x0C, 0x22, 0xA1}, {0x0C, 0x28, 0xA8}, {0x0C, 0x2A, 0xB4}, {0x0C, 0x2B, 0xB5}, {0x0C, 0x2C, 0xB6},
    {0x0C, 0x2D, 0xB7}, {0x0C, 0x2E, 0xB8}, {0x0C, 0x2F, 0xB9}, {0x0C, 0x31, 0xB1}, {0x0C, 0x32, 0xB2},
    {0x0C, 0x33, 0xB3}, {0x0C, 0x37, 0x9A}, {0x0C, 0x38, 0x9B}, {0x0C, 0x39, 0x9B}, {0x0C, 0x3A, 0x9C},
    {0x0C, 0x3B, 0x9D}, {0x0C, 0x40, 0x87}, {0x0C, 0x41, 0xC1}, {0x0C, 0x42, 0xC2}, {0x0C, 0x43, 0xC3},
    {0x0C, 0x50, 0x8B}, {0x0C, 0x51, 0x97}, {0x0C, 0x52, 0xD2}, {0x0C, 0x53, 0xD3}, {0x0C, 0x54, 0xD4},
    {0x0D, 0x13, 0x83}, {0x0D, 0x15, 0x86}, {0x0D, 0x1A, 0x89}, {0x0D, 0x1B, 0x8A}, {0x0D, 0x1C, 0x8B},
    {0x0D, 0x1D, 0x8C}, {0x0D, 0x20, 0x8E}, {0x0D, 0x28, 0x93}, {0x0D, 0x43, 0xB2}, {0x0D, 0x50, 0xD0},
    {0x0D, 0x52, 0xD2}, {0x0D, 0x53, 0xD3}, {0x0D, 0x54, 0xD4}, {0x0D, 0x55, 0xD5}, {0x0D, 0x56, 0xD6},
    {0x0D, 0x61, 0xE1}, {0x0D, 0x63, 0xE3}, {0x0D, 0x64, 0xE4}, {0x0E, 0x01, 0x81}, {0x0E, 0x02, 0x82},
    {0x0E, 0x20, 0xA0},
};

constexpr std::uint8_t kSpeedLeverArm = 0x61;  // (0x0D,0x61)
// Lever arms with a documented 10 m magnitude limit (digest §6.9: 0x0D,0x13 L8276, 0x0D,0x54
// L8617, 0x0D,0x56 L8665) and the offset of their Vector3f in the written data.
constexpr std::uint8_t kAntennaOffset = 0x13, kMultiAntennaOffset = 0x54, kReferencePointLeverArm = 0x56;
constexpr double kMaxLeverArmM = 10.0;

// True when a Write of a limited lever arm asks for more than 10 m: the device refuses it.
bool lever_arm_beyond_limit(std::uint8_t desc, std::span<const std::uint8_t> data) {
  std::size_t at = 0;
  switch (desc) {
    case kAntennaOffset: at = 1; break;
    case kMultiAntennaOffset: case kReferencePointLeverArm: at = 2; break;
    default: return false;
  }
  bytes::Reader<bytes::Endian::kBig> r(data.subspan(std::min(at, data.size())));
  const double x = r.f32(), y = r.f32(), z = r.f32();
  return !r.ok() || !(std::sqrt(x * x + y * y + z * z) <= kMaxLeverArmM);
}
constexpr std::uint8_t kAidingControl = 0x50;  // (0x0D,0x50)
constexpr std::uint8_t kInitialHeading = 0x03;  // (0x0D,0x03): heading [rad] in [-pi, pi] (digest §6.4)
constexpr std::uint16_t kLastAidingSource = 8;  // BODY_FRAME_VEL; 0xFFFF (ALL) is not for Write (digest §6.5)
constexpr std::uint8_t kExternalHeading = 0x17, kExternalHeadingWithTime = 0x1F;  // (0x0D,..), legacy
constexpr std::uint8_t kHeadingTypeTrue = 1, kHeadingTypeMagnetic = 2;
// Headings are f32: +-pi as a client writes it rounds to just beyond the double pi.
constexpr double kMaxHeadingRad = static_cast<float>(std::numbers::pi);

// (0x0D,0x17) / (0x0D,0x1F) (digest §6.8, L8322-8420): a heading beyond +-pi or an uncertainty
// <= 0 is an invalid parameter ("<= 0 NACKed"); a magnetic heading needs a declination the
// device link does not have: command failed, so the client knows it was not used.
ReplyCode check_external_heading(std::uint8_t desc, std::span<const std::uint8_t> data) {
  bytes::Reader<bytes::Endian::kBig> r(data);
  if (desc == kExternalHeadingWithTime) {
    r.f64();  // GPS time of week
    r.u16();  // week
  }
  const double heading = r.f32(), uncertainty = r.f32();
  const std::uint8_t type = r.u8();
  if (!r.ok() || !(std::abs(heading) <= kMaxHeadingRad) || !(uncertainty > 0)) return ReplyCode::kInvalidParameter;
  if (type == kHeadingTypeMagnetic) return ReplyCode::kCommandFailed;
  return type == kHeadingTypeTrue ? ReplyCode::kAck : ReplyCode::kInvalidParameter;
}

int response_desc(std::uint8_t s, std::uint8_t cmd) {
  for (const auto& r : kResponses)
    if (r.set == s && r.cmd == cmd) return r.resp;
  return -1;
}

// Documented base rates (L2686-2698) for (0x0C,0x0E).
int base_rate_hz(std::uint8_t data_set) {
  switch (data_set) {
    case set::kSensor: case set::kFilter: case set::kSystem: return 1000;
    case set::kGnss1: case set::kGnss2: return 5;
    case set::kGnssCorrections: case set::kGnssExternal: return 0;
    default: return -1;
  }
}

constexpr std::uint8_t kDeviceInfo = 0x03, kDescriptors = 0x04, kBuiltInTest = 0x05, kExtDescriptors = 0x07,
                       kContinuousBit = 0x08, kIdle = 0x02, kResume = 0x06;
constexpr std::uint8_t kBaseRate = 0x0E, kStreamControl = 0x11;
constexpr std::size_t kIdentityStringSize = 16;
constexpr std::size_t kCbitBytes = 16;

void put_string(bytes::BeWriter& w, const std::string& s) {
  for (std::size_t i = 0; i < kIdentityStringSize; ++i) w.u8(i < s.size() ? static_cast<std::uint8_t>(s[i]) : 0);
}

}  // namespace

CommandResponder::CommandResponder(DeviceIdentity identity, const time::ClockModel* clock)
    : identity_(std::move(identity)), aiding_(clock) {}

bool CommandResponder::stream_enabled(std::uint8_t data_set) const {
  const auto it = streams_.find(data_set);
  return it == streams_.end() || it->second;
}

void CommandResponder::handle_packet(std::span<const std::uint8_t> packet, std::vector<std::uint8_t>& reply,
                                     std::vector<Measurement>& aiding, std::int64_t arrival_gps_ns) {
  reply.clear();
  aiding.clear();
  if (packet.size() < kWrapperSize || packet[0] != kSync1 || packet[1] != kSync2) return;
  const std::size_t n = packet[kLengthOffset];
  if (packet.size() < n + kWrapperSize) return;
  const std::uint8_t desc_set = packet[kSetOffset];
  if (!set::is_command(desc_set)) return;  // data packets are not answered
  const auto body = packet.first(kHeaderSize + n);
  const auto payload = body.subspan(kHeaderSize);
  if (!fields_well_formed(payload)) return;
  const bool checksum_ok =
      bytes::mip_fletcher(body) == static_cast<std::uint16_t>((packet[body.size()] << 8) | packet[body.size() + 1]);
  if (desc_set == set::kAiding && checksum_ok) {
    AidingResult r;
    aiding_.handle_payload(payload, r, arrival_gps_ns);
    reply = std::move(r.reply);
    aiding = std::move(r.measurements);
    return;
  }
  PacketWriter w(reply, desc_set);
  std::vector<std::uint8_t> response;
  FieldWalker walk(payload);
  FieldView f;
  while (walk.next(f)) {
    response.clear();
    const ReplyCode code = checksum_ok ? handle_command(desc_set, f.desc, f.data, response) : ReplyCode::kBadChecksum;
    auto& ack = w.field(kAckNackDescriptor);
    ack.u8(f.desc);
    ack.u8(static_cast<std::uint8_t>(code));
    if (code == ReplyCode::kAck && !response.empty())
      w.raw_field(response[0], std::span<const std::uint8_t>(response).subspan(1));
  }
  w.finish();
}

ReplyCode CommandResponder::handle_command(std::uint8_t desc_set, std::uint8_t desc, std::span<const std::uint8_t> data,
                                           std::vector<std::uint8_t>& response) {
  if (desc >= 0x80) return ReplyCode::kUnknownCommand;  // replies are not commands
  const FieldSchema* s = find_schema(desc_set, desc, data);
  if (s == nullptr) {
    bool set_known = false;
    for (const auto& c : command_schemas()) set_known |= c.set == desc_set;
    return set_known ? ReplyCode::kUnknownCommand : ReplyCode::kUnknownDescriptorSet;
  }
  const bool refused = std::find(refused_.begin(), refused_.end(), std::pair{desc_set, desc}) != refused_.end();
  if (refused && (!s->has_function || (!data.empty() && data[0] == static_cast<std::uint8_t>(Function::kWrite)))) {
    return ReplyCode::kCommandFailed;
  }
  bytes::BeWriter out(response);
  const int resp = response_desc(desc_set, desc);
  if (desc_set == set::kBase) {
    switch (desc) {
      case kIdle: idle_ = true; return ReplyCode::kAck;
      case kResume: idle_ = false; return ReplyCode::kAck;
      case kDeviceInfo:
        response.push_back(static_cast<std::uint8_t>(resp));
        out.u16(identity_.firmware_version);
        put_string(out, identity_.model_name);
        put_string(out, identity_.model_number);
        put_string(out, identity_.serial_number);
        put_string(out, identity_.lot_number);
        put_string(out, identity_.device_options);
        return ReplyCode::kAck;
      case kDescriptors:
      case kExtDescriptors:
        response.push_back(static_cast<std::uint8_t>(resp));
        // Each u16: MSB descriptor set, LSB descriptor (L8072); the data fields navfuse decodes.
        for (const auto& d : data_schemas()) {
          if (response.size() + 2 > kMaxFieldData) break;
          if (d.set != set::kShared) out.u16(static_cast<std::uint16_t>((d.set << 8) | d.desc));
        }
        return ReplyCode::kAck;
      case kBuiltInTest:
        response.push_back(static_cast<std::uint8_t>(resp));
        out.u32(0);  // 0 = all passed (L8087)
        return ReplyCode::kAck;
      case kContinuousBit:
        response.push_back(static_cast<std::uint8_t>(resp));
        out.zeros(kCbitBytes);
        return ReplyCode::kAck;
      default: break;
    }
  }
  if (desc_set == set::k3dm && desc == kBaseRate) {
    if (data.empty() || base_rate_hz(data[0]) < 0) return ReplyCode::kInvalidParameter;
    response.push_back(static_cast<std::uint8_t>(resp));
    out.u8(data[0]);
    out.u16(static_cast<std::uint16_t>(base_rate_hz(data[0])));
    return ReplyCode::kAck;
  }
  if (!s->has_function) {
    std::size_t group = 0;
    if (data.size() < fixed_size(*s, &group)) return ReplyCode::kInvalidParameter;
    if (desc_set == set::kFilterCmd && (desc == kExternalHeading || desc == kExternalHeadingWithTime)) {
      return check_external_heading(desc, data);
    }
    if (desc_set == set::kFilterCmd && desc == kInitialHeading) {
      bytes::Reader<bytes::Endian::kBig> r(data);
      const double heading = r.f32();
      return std::abs(heading) <= kMaxHeadingRad ? ReplyCode::kAck : ReplyCode::kInvalidParameter;
    }
    return ReplyCode::kAck;  // actions (reset, run, capture...) are acknowledged
  }
  if (data.empty()) return ReplyCode::kInvalidParameter;
  const auto fn = static_cast<Function>(data[0]);
  // Key bytes: the parameters that select which setting (e.g. the descriptor set).
  std::size_t key_bytes = 0;
  for (std::size_t i = 1; i <= s->key_params && i < s->params.size(); ++i) key_bytes += wire_size(s->params[i].type);
  constexpr std::size_t kMaxKeyBytes = 4;
  if (data.size() < 1 + key_bytes || key_bytes > kMaxKeyBytes) return ReplyCode::kInvalidParameter;
  std::uint64_t key = (std::uint64_t{desc_set} << 48) | (std::uint64_t{desc} << 40) | (std::uint64_t{key_bytes} << 32);
  for (std::size_t i = 0; i < key_bytes; ++i) key |= std::uint64_t{data[1 + i]} << (8 * (kMaxKeyBytes - 1 - i));
  const auto key_span = data.subspan(1, key_bytes);
  switch (fn) {
    case Function::kWrite: {
      std::size_t group = 0;
      const std::size_t fixed = fixed_size(*s, &group);
      if (data.size() < fixed || (group > 0 && (data.size() - fixed) % group != 0)) return ReplyCode::kInvalidParameter;
      if (desc_set == set::k3dm && (desc == kSensorToVehicleQuaternion || desc == kSensorToVehicleDcm) &&
          !sensor_to_vehicle_dcm(desc, data.subspan(1))) {
        return ReplyCode::kInvalidParameter;
      }
      // Speed measurement lever arm: "source ... reserved, must be 1" (digest §6.15, L8688).
      if (desc_set == set::kFilterCmd && desc == kSpeedLeverArm && data[1] != 1) return ReplyCode::kInvalidParameter;
      if (desc_set == set::kFilterCmd && lever_arm_beyond_limit(desc, data)) return ReplyCode::kInvalidParameter;
      if (desc_set == set::kFilterCmd && desc == kAidingControl && ((data[1] << 8) | data[2]) > kLastAidingSource) {
        return ReplyCode::kInvalidParameter;
      }
      settings_[key].assign(data.begin() + 1 + static_cast<std::ptrdiff_t>(key_bytes), data.end());
      if (desc_set == set::k3dm && desc == kStreamControl && data.size() >= 3) streams_[data[1]] = data[2] != 0;
      return ReplyCode::kAck;
    }
    case Function::kRead: {
      if (resp < 0) return ReplyCode::kAck;
      response.push_back(static_cast<std::uint8_t>(resp));
      out.bytes(key_span);
      const auto it = settings_.find(key);
      if (it != settings_.end()) {
        out.bytes(it->second);
      } else {
        std::size_t group = 0;
        const std::size_t fixed = fixed_size(*s, &group);
        out.zeros(fixed > 1 + key_bytes ? fixed - 1 - key_bytes : 0);
      }
      return ReplyCode::kAck;
    }
    case Function::kSave:
    case Function::kLoad: return ReplyCode::kAck;
    case Function::kDefault:
      settings_.erase(key);
      if (desc_set == set::k3dm && desc == kStreamControl && !data.empty()) streams_.clear();
      return ReplyCode::kAck;
  }
  return ReplyCode::kInvalidParameter;
}

}  // namespace navfuse::frontends::mip

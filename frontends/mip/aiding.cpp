#include "frontends/mip/aiding.hpp"

#include <cmath>

#include "core/bytes/byte_reader.hpp"
#include "core/bytes/checks.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/mip/packet.hpp"
#include "frontends/mip/units.hpp"
#include "frontends/mip/writer.hpp"

namespace navfuse::frontends::mip {
namespace {

// 0x13 descriptors (digest §5.2-§5.3).
constexpr std::uint8_t kFrameConfig = 0x01, kFrameConfigResponse = 0x81;
constexpr std::uint8_t kEchoControl = 0x1F, kEchoControlResponse = 0x9F;
constexpr std::uint8_t kPosEcef = 0x21, kPosLlh = 0x22, kHeight = 0x23;
constexpr std::uint8_t kVelEcef = 0x28, kVelNed = 0x29, kVelBody = 0x2A;
constexpr std::uint8_t kHeadingTrue = 0x31, kMagField = 0x32, kPressure = 0x33;
constexpr std::uint8_t kFormatEuler = 1, kFormatQuaternion = 2;
constexpr std::uint16_t kAxisBits = 0x7;

struct Header {
  std::int64_t time_ns = 0;
  TimeSource source = TimeSource::kUnknown;
  std::uint8_t frame_id = 0;
};

Eigen::Vector3d read_v3f(bytes::BeReader& r) {
  const double x = r.f32(), y = r.f32(), z = r.f32();
  return {x, y, z};
}
Eigen::Vector3d read_v3d(bytes::BeReader& r) {
  const double x = r.f64(), y = r.f64(), z = r.f64();
  return {x, y, z};
}

// Every valid axis needs a finite value and an uncertainty > 0 (L783, L7829); NaN uncertainty fails too.
bool axes_ok(const Eigen::Vector3d& value, const Eigen::Vector3d& std, std::uint16_t valid) {
  for (int i = 0; i < 3; ++i) {
    if (!(valid & (1u << i))) continue;
    if (!std::isfinite(value[i]) || !(std[i] > 0.0) || !std::isfinite(std[i])) return false;
  }
  return true;
}

// Rotates a per-axis measurement from the aiding frame into the vehicle frame. A vehicle axis is
// valid only when it does not depend on an invalid sensor axis (so a 90-degree mounting maps
// validity exactly, and an oblique one keeps only what is determined); its 1-sigma follows from
// independent sensor axes: var_i = sum_j R_ij^2 var_j.
void rotate_axes(const Eigen::Matrix3d& r, const Eigen::Vector3d& value, const Eigen::Vector3d& std,
                 std::uint16_t valid, Eigen::Vector3d& value_out, Eigen::Vector3d& std_out, std::uint32_t& valid_out) {
  // Angles arrive as float32: a right angle leaves cos ~ 4e-8, which must still count as zero.
  constexpr double kIndependent = 1e-6;
  valid_out = 0;
  for (int i = 0; i < 3; ++i) {
    double v = 0.0, var = 0.0;
    bool ok = true;
    for (int j = 0; j < 3; ++j) {
      const bool vj = valid & (1u << j);
      if (!vj) {
        if (std::abs(r(i, j)) > kIndependent) ok = false;
        continue;
      }
      v += r(i, j) * value[j];
      var += r(i, j) * r(i, j) * std[j] * std[j];
    }
    value_out[i] = ok ? v : 0.0;
    std_out[i] = ok ? std::sqrt(var) : 0.0;
    if (ok) valid_out |= 1u << i;
  }
}

}  // namespace

void AidingCommandHandler::handle_packet(std::span<const std::uint8_t> packet, AidingResult& out,
                                         std::int64_t arrival_gps_ns) {
  out.reply.clear();
  out.measurements.clear();
  out.codes.clear();
  if (packet.size() < kWrapperSize || packet[0] != kSync1 || packet[1] != kSync2) return;
  const std::size_t payload_len = packet[kLengthOffset];
  if (packet.size() < payload_len + kWrapperSize) return;
  const auto body = packet.first(kHeaderSize + payload_len);
  const auto payload = body.subspan(kHeaderSize);
  const std::uint8_t desc_set = packet[kSetOffset];
  const std::uint16_t sent = static_cast<std::uint16_t>((packet[body.size()] << 8) | packet[body.size() + 1]);
  const bool checksum_ok = bytes::mip_fletcher(body) == sent;
  if (!fields_well_formed(payload)) return;  // nothing identifiable to answer
  if (checksum_ok && desc_set == set::kAiding) {
    handle_payload(payload, out, arrival_gps_ns);
    return;
  }
  // A bad checksum or a foreign set: NACK every command field with the matching code (L8873-8881).
  const ReplyCode code = checksum_ok ? ReplyCode::kUnknownDescriptorSet : ReplyCode::kBadChecksum;
  PacketWriter w(out.reply, desc_set);
  FieldWalker walk(payload);
  FieldView f;
  while (walk.next(f)) {
    auto& ack = w.field(kAckNackDescriptor);
    ack.u8(f.desc);
    ack.u8(static_cast<std::uint8_t>(code));
    out.codes.emplace_back(f.desc, code);
  }
  w.finish();
}

void AidingCommandHandler::handle_payload(std::span<const std::uint8_t> payload, AidingResult& out,
                                          std::int64_t arrival_gps_ns) {
  out.reply.clear();
  out.measurements.clear();
  out.codes.clear();
  PacketWriter w(out.reply, set::kAiding);
  std::vector<std::uint8_t> response;
  bool any_field = false;
  FieldWalker walk(payload);
  FieldView f;
  while (walk.next(f)) {
    if (f.desc >= 0x80) continue;  // replies/responses are not commands (L3852)
    response.clear();
    ReplyCode code = ReplyCode::kUnknownCommand;
    bool is_measurement = false;
    switch (f.desc) {
      case kFrameConfig: code = frame_config(f.data, response); break;
      case kEchoControl: code = echo_control(f.data, response); break;
      case kPosEcef: case kPosLlh: case kHeight: case kVelEcef: case kVelNed: case kVelBody:
      case kHeadingTrue: case kMagField: case kPressure:
        is_measurement = true;
        code = measurement(f.desc, f.data, arrival_gps_ns, out.measurements);
        break;
      default: break;
    }
    out.codes.emplace_back(f.desc, code);
    // SUPPRESS_ACK mutes the ACK of aiding measurements only (L7791); NACKs are still sent.
    if (is_measurement && code == ReplyCode::kAck && echo_ == AidingEchoMode::kSuppressAck) continue;
    auto& ack = w.field(kAckNackDescriptor);
    ack.u8(f.desc);
    ack.u8(static_cast<std::uint8_t>(code));
    any_field = true;
    if (code == ReplyCode::kAck && response.size() >= kFieldHeaderSize) {
      // Response data follows its ACK in the same packet, never when NACKed (L3852).
      w.raw_field(response[0], std::span<const std::uint8_t>(response).subspan(1));
    }
  }
  if (any_field) {
    w.finish();
  } else {
    out.reply.clear();
  }
}

ReplyCode AidingCommandHandler::frame_config(std::span<const std::uint8_t> data, std::vector<std::uint8_t>& response) {
  bytes::BeReader r(data);
  const auto fn = static_cast<Function>(r.u8());
  const std::uint8_t id = r.u8();
  if (!r.ok()) return ReplyCode::kInvalidParameter;
  // Frame 0 is the device itself; user frames are 1..4 (L7755 "Limit 4", errata E8).
  if (id == 0 || id >= kFrames) return ReplyCode::kInvalidParameter;
  AidingFrame& frame = frames_[id];
  switch (fn) {
    case Function::kWrite: {
      const std::uint8_t format = r.u8();
      const bool tracking = r.u8() != 0;
      const Eigen::Vector3d t = read_v3f(r);
      Eigen::Quaterniond q;
      if (format == kFormatEuler) {
        // Errata E9: an Euler rotation is 3 floats (SDK), roll-pitch-yaw of the 3-2-1 sequence,
        // taken like the sensor-to-vehicle Euler (digest §6.1 examples L2511-2551): R = C(rpy)
        // as rot::dcm_from_rpy builds it, p_vehicle = R p_sensor.
        q = rot::quat_from_rpy(read_v3f(r));
      } else if (format == kFormatQuaternion) {
        const double qw = r.f32(), qx = r.f32(), qy = r.f32(), qz = r.f32();
        q = Eigen::Quaterniond(qw, qx, qy, qz);
        if (!(q.norm() > 0.5 && q.norm() < 1.5)) return ReplyCode::kInvalidParameter;
        q.normalize();
      } else {
        return ReplyCode::kInvalidParameter;
      }
      if (!r.ok() || !t.allFinite() || !q.coeffs().allFinite()) return ReplyCode::kInvalidParameter;
      frame.configured = true;
      frame.format = format;
      frame.tracking_enabled = tracking;
      frame.translation_m = t;
      frame.rotation = q;
      return ReplyCode::kAck;
    }
    case Function::kRead: {
      if (!frame.configured) return ReplyCode::kInvalidParameter;
      const std::uint8_t format = data.size() > 2 ? data[2] : frame.format;
      if (format != kFormatEuler && format != kFormatQuaternion) return ReplyCode::kInvalidParameter;
      response.push_back(kFrameConfigResponse);
      bytes::BeWriter w(response);
      w.u8(id);
      w.u8(format);
      w.u8(frame.tracking_enabled ? 1 : 0);
      for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(frame.translation_m[i]));
      if (format == kFormatEuler) {
        const Eigen::Vector3d rpy = rot::rpy_from_quat(frame.rotation);
        for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(rpy[i]));
      } else {
        w.f32(static_cast<float>(frame.rotation.w()));
        w.f32(static_cast<float>(frame.rotation.x()));
        w.f32(static_cast<float>(frame.rotation.y()));
        w.f32(static_cast<float>(frame.rotation.z()));
      }
      return ReplyCode::kAck;
    }
    case Function::kSave:
    case Function::kLoad:
      return ReplyCode::kAck;  // no non-volatile memory: the running frame is what would be saved
    case Function::kDefault:
      frame = AidingFrame{};
      return ReplyCode::kAck;
  }
  return ReplyCode::kInvalidParameter;
}

ReplyCode AidingCommandHandler::echo_control(std::span<const std::uint8_t> data, std::vector<std::uint8_t>& response) {
  bytes::BeReader r(data);
  const auto fn = static_cast<Function>(r.u8());
  if (!r.ok()) return ReplyCode::kInvalidParameter;
  switch (fn) {
    case Function::kWrite: {
      const std::uint8_t mode = r.u8();
      if (!r.ok() || mode > static_cast<std::uint8_t>(AidingEchoMode::kResponse)) return ReplyCode::kInvalidParameter;
      // RESPONSE mode (echo the data back) serves MicroStrain's desktop simulator (L751-753);
      // navfuse acknowledges it like STANDARD.
      echo_ = static_cast<AidingEchoMode>(mode);
      return ReplyCode::kAck;
    }
    case Function::kRead:
      response.push_back(kEchoControlResponse);
      response.push_back(static_cast<std::uint8_t>(echo_));
      return ReplyCode::kAck;
    case Function::kSave:
    case Function::kLoad:
      return ReplyCode::kAck;
    case Function::kDefault:
      echo_ = AidingEchoMode::kStandard;
      return ReplyCode::kAck;
  }
  return ReplyCode::kInvalidParameter;
}

ReplyCode AidingCommandHandler::measurement(std::uint8_t desc, std::span<const std::uint8_t> data,
                                            std::int64_t arrival_gps_ns, std::vector<Measurement>& out) {
  bytes::BeReader r(data);
  // `Time` (digest §5.1): u8 timebase, u8 reserved, u64 ns; then u8 frame_id.
  const std::uint8_t timebase = r.u8();
  r.u8();
  const std::uint64_t ns = r.u64();
  Header h;
  h.frame_id = r.u8();
  if (!r.ok()) return ReplyCode::kInvalidParameter;
  switch (static_cast<AidingTimebase>(timebase)) {
    case AidingTimebase::kInternalReference: {
      const auto gps = clock_ ? clock_->to_gps(static_cast<std::int64_t>(ns)) : std::nullopt;
      h.time_ns = gps ? *gps : static_cast<std::int64_t>(ns);
      h.source = gps ? TimeSource::kGps : TimeSource::kDeviceMonotonic;
      break;
    }
    case AidingTimebase::kExternalTime:
      h.time_ns = static_cast<std::int64_t>(ns);
      h.source = TimeSource::kGps;
      break;
    case AidingTimebase::kTimeOfArrival:
      // The caller's arrival time is GPS time (the nav process passes the GPS time of its newest
      // IMU epoch), so the measurement is on the IMU's time axis. Without one (decoding a log)
      // the arrival time is unknown.
      h.time_ns = arrival_gps_ns;
      h.source = arrival_gps_ns > 0 ? TimeSource::kGps : TimeSource::kHostArrival;
      break;
    default:
      return ReplyCode::kInvalidParameter;
  }
  if (h.frame_id >= kFrames || (h.frame_id != 0 && !frames_[h.frame_id].configured))
    return ReplyCode::kInvalidParameter;  // unknown aiding frame
  const AidingFrame& frame = frames_[h.frame_id];
  const Eigen::Matrix3d rot_vs = frame.rotation.toRotationMatrix();
  MeasurementHeader mh;
  mh.time_ns = h.time_ns;
  mh.time_source = h.source;

  switch (desc) {
    case kPosEcef:
    case kPosLlh: {
      Eigen::Vector3d value = read_v3d(r);
      const Eigen::Vector3d std = read_v3f(r);
      const std::uint16_t valid = r.u16();
      if (!r.ok() || !axes_ok(value, std, valid)) return ReplyCode::kInvalidParameter;
      ExternalPosition m;
      m.header = mh;
      m.header.valid = valid & kAxisBits;
      m.frame = desc == kPosEcef ? PositionFrame::kEcef : PositionFrame::kLlh;
      if (desc == kPosLlh) {
        // Degrees on the wire (L7841); LLH uncertainty is N/E/D metres, not degrees (L763).
        value.x() *= rot::kDegToRad;
        value.y() *= rot::kDegToRad;
      }
      m.value = value;
      m.std_m = std;
      m.lever_arm_m = frame.translation_m;  // the sensor's position in the vehicle frame
      if (m.header.valid) out.emplace_back(m);
      return ReplyCode::kAck;
    }
    case kHeight: {
      const double height = r.f32(), std = r.f32();
      const std::uint16_t valid = r.u16();
      // Scalar valid flags have no documented bits; bit0 is taken as "valid" (digest §5.4).
      if (!r.ok() || !axes_ok({0, 0, height}, {1, 1, std}, static_cast<std::uint16_t>((valid & 1u) << 2)))
        return ReplyCode::kInvalidParameter;
      ExternalPosition m;
      m.header = mh;
      m.header.valid = (valid & 1u) ? ExternalPosition::kValidZ : 0;
      m.frame = PositionFrame::kLlh;
      m.value = {0.0, 0.0, height};
      m.std_m = {0.0, 0.0, std};
      m.lever_arm_m = frame.translation_m;
      if (m.header.valid) out.emplace_back(m);
      return ReplyCode::kAck;
    }
    case kVelEcef:
    case kVelNed:
    case kVelBody: {
      const Eigen::Vector3d value = read_v3f(r);
      const Eigen::Vector3d std = read_v3f(r);
      const std::uint16_t valid = r.u16();
      if (!r.ok() || !axes_ok(value, std, valid)) return ReplyCode::kInvalidParameter;
      ExternalVelocity m;
      m.header = mh;
      m.lever_arm_m = frame.translation_m;
      if (desc == kVelBody) {
        // Velocity measured along the aiding frame's axes (L7928): v_vehicle = R v_sensor.
        std::uint32_t vv = 0;
        rotate_axes(rot_vs, value, std, valid & kAxisBits, m.value_mps, m.std_mps, vv);
        m.header.valid = vv;
        m.frame = VelocityFrame::kVehicle;
      } else {
        m.header.valid = valid & kAxisBits;
        m.value_mps = value;
        m.std_mps = std;
        m.frame = desc == kVelEcef ? VelocityFrame::kEcef : VelocityFrame::kNed;
      }
      if (m.header.valid) out.emplace_back(m);
      return ReplyCode::kAck;
    }
    case kHeadingTrue: {
      const double heading = r.f32(), std = r.f32();
      const std::uint16_t valid = r.u16();
      if (!r.ok() || !axes_ok({heading, 0, 0}, {std, 1, 1}, valid & 1u)) return ReplyCode::kInvalidParameter;
      ExternalHeading m;
      m.header = mh;
      m.header.valid = (valid & 1u) ? ExternalHeading::kValidHeading : 0;
      // The heading is that of the aiding frame's x axis; the vehicle's is offset by the
      // azimuth of that axis in the vehicle frame.
      const double mount_azimuth = std::atan2(rot_vs(1, 0), rot_vs(0, 0));
      m.heading_rad = rot::wrap_pi(heading - mount_azimuth);
      m.std_rad = std;
      if (m.header.valid) out.emplace_back(m);
      return ReplyCode::kAck;
    }
    case kMagField: {
      const Eigen::Vector3d value = read_v3f(r);
      const Eigen::Vector3d std = read_v3f(r);
      const std::uint16_t valid = r.u16();
      if (!r.ok() || !axes_ok(value, std, valid)) return ReplyCode::kInvalidParameter;
      Eigen::Vector3d v, s;
      std::uint32_t vv = 0;
      rotate_axes(rot_vs, value, std, valid & kAxisBits, v, s, vv);
      // Core Magnetometer carries a whole vector: emitted only when every vehicle axis is known.
      if (vv == kAxisBits) {
        Magnetometer m;
        m.header = mh;
        m.header.valid = Magnetometer::kValidField;
        m.frame = SensorFrame::kVehicle;
        m.field_gauss = v;
        out.emplace_back(m);
      }
      return ReplyCode::kAck;
    }
    case kPressure: {
      const double mbar = r.f32(), std = r.f32();
      const std::uint16_t valid = r.u16();
      if (!r.ok() || !axes_ok({mbar, 0, 0}, {std, 1, 1}, valid & 1u)) return ReplyCode::kInvalidParameter;
      if (valid & 1u) {
        Pressure m;
        m.header = mh;
        m.header.valid = Pressure::kValidPressure;
        m.pressure_pa = mbar * kMbarToPa;
        out.emplace_back(m);
      }
      return ReplyCode::kAck;
    }
    default:
      return ReplyCode::kUnknownCommand;
  }
}

}  // namespace navfuse::frontends::mip

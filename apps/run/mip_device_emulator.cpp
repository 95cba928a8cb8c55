#include "apps/run/mip_device_emulator.hpp"

#include <cmath>
#include <optional>

#include "core/bytes/byte_reader.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "filter/engine.hpp"
#include "frontends/mip/commands.hpp"
#include "frontends/mip/encoder_calibration.hpp"
#include "frontends/mip/encoder_solution.hpp"
#include "frontends/mip/packet.hpp"
#include "frontends/mip/sensor_to_vehicle.hpp"

namespace navfuse::apps {
namespace {

namespace mip = frontends::mip;

constexpr std::size_t kMaxClients = 16;  // framers kept; the oldest client's goes first
constexpr std::uint8_t kFunctionWrite = 0x01;
constexpr std::uint8_t kResetFilter = 0x01;            // (0x0D,0x01)
constexpr std::uint8_t kInitialHeading = 0x03;         // (0x0D,0x03)
constexpr std::uint8_t kAntennaOffset = 0x13;          // (0x0D,0x13), the primary antenna
constexpr std::uint8_t kExternalHeading = 0x17;        // (0x0D,0x17), legacy
constexpr std::uint8_t kExternalHeadingWithTime = 0x1F;  // (0x0D,0x1F), legacy
constexpr std::uint8_t kAidingControl = 0x50;          // (0x0D,0x50)
constexpr std::uint8_t kMultiAntennaOffset = 0x54;     // (0x0D,0x54)
constexpr std::uint8_t kSpeedLeverArm = 0x61;          // (0x0D,0x61)
constexpr std::uint8_t kWheeledVehicle = 0x63;         // (0x0D,0x63)

// Filter-configuration and aiding commands of the CV7 (digest §6, §7.2-7.3) that the engine
// cannot take at run time: its noise models, initialisation, aiding selection and constraints
// come from the config file. NACKed "command failed" so that a client knows the setting did not
// take. Sensor calibration writes (user biases, magnetometer iron, odometer) too: navfuse
// fuses the input device's calibrated data and has no place to apply them.
constexpr std::pair<std::uint8_t, std::uint8_t> kRefused[] = {
    {0x0C, 0x37},  // accel bias
    {0x0C, 0x38},  // gyro bias
    {0x0C, 0x39},  // capture gyro bias
    {0x0C, 0x3A},  // mag hard iron offset
    {0x0C, 0x3B},  // mag soft iron matrix
    {0x0C, 0x43},  // odometer configuration
    {0x0C, 0x51},  // complementary filter configuration
    {0x0D, 0x15},  // GNSS aiding source
    {0x0D, 0x1A},  // accel noise std
    {0x0D, 0x1B},  // gyro noise std
    {0x0D, 0x1C},  // accel bias model
    {0x0D, 0x1D},  // gyro bias model
    {0x0D, 0x20},  // zero angular rate update control
    {0x0D, 0x28},  // gravity noise std
    {0x0D, 0x43},  // declination source
    {0x0D, 0x52},  // navigation filter initialization
    {0x0D, 0x53},  // adaptive filter
    {0x0D, 0x55},  // relative position configuration
    {0x0D, 0x56},  // reference point lever arm
    {0x0D, 0x64},  // GNSS antenna offset calibration
};

Eigen::Vector3d read_vec3f(bytes::Reader<bytes::Endian::kBig>& r) {
  const double x = r.f32();
  const double y = r.f32();
  const double z = r.f32();
  return {x, y, z};
}

// CV7 aiding sources (0x0D,0x50; digest §6.5, L8500-8512) -> the measurement kinds they feed.
// Internal and external altimeter alike are pressure, internal and external magnetometer alike
// the magnetometer; speed is every odometry kind; body-frame velocity is external velocity.
std::vector<MeasurementKind> kinds_of_aiding_source(std::uint16_t source) {
  using K = MeasurementKind;
  switch (source) {
    case 0: return {K::kGnssPosition, K::kGnssVelocity};
    case 1: return {K::kGnssHeading};
    case 2: case 6: return {K::kPressure};
    case 3: return {K::kWheelSpeed, K::kVehicleSpeed, K::kWheelTicks};
    case 4: case 7: return {K::kMagnetometer};
    case 5: return {K::kExternalHeading};
    case 8: return {K::kExternalVelocity};
    default: return {};
  }
}

}  // namespace

MipDeviceEmulator::MipDeviceEmulator(const Eigen::Vector3d& mounting_rpy_rad, const Eigen::Vector3d& gnss_lever_arm_m,
                                     bool device_link)
    : c_vs_(rot::dcm_from_rpy(mounting_rpy_rad)), gnss_lever_arm_m_(gnss_lever_arm_m), device_link_(device_link) {
  responder_.refuse({std::begin(kRefused), std::end(kRefused)});
}

void MipDeviceEmulator::stream(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) {
  last_epoch_gps_ns_ = epoch.solution.header.time_ns;
  if (responder_.idle() || !responder_.stream_enabled(mip::set::kFilter)) return;
  encoder_.append(epoch, out);
  if (device_link_ && epoch.pose_due) mip::encode_calibration(epoch.solution, gnss_lever_arm_m_, out);
}

mip::Framer& MipDeviceEmulator::framer_for(io::PeerId peer) {
  auto it = framers_.find(peer);
  if (it != framers_.end()) return *it->second;
  // Peer ids only grow, so the smallest belongs to the client that connected first.
  if (framers_.size() >= kMaxClients) framers_.erase(framers_.begin());
  return *framers_.emplace(peer, std::make_unique<mip::Framer>()).first->second;
}

void MipDeviceEmulator::receive(io::PeerId peer, std::span<const std::uint8_t> bytes,
                                std::vector<std::uint8_t>& reply, CommandEffects& effects) {
  framer_for(peer).feed(bytes, [&](const mip::PacketView& packet) {
    if (!mip::set::is_command(packet.desc_set)) return;  // data echoed back is not for us
    packet_reply_.clear();
    packet_aiding_.clear();
    responder_.handle_packet(packet.bytes, packet_reply_, packet_aiding_, last_epoch_gps_ns_);
    reply.insert(reply.end(), packet_reply_.begin(), packet_reply_.end());
    effects.aiding.insert(effects.aiding.end(), packet_aiding_.begin(), packet_aiding_.end());
    if (acknowledged_any()) engine_effects(packet, effects);
  });
}

bool MipDeviceEmulator::acknowledged_any() {
  acked_.clear();
  mip::Framer framer;
  std::vector<mip::ReplyEntry> entries;
  framer.feed(packet_reply_, [&](const mip::PacketView& p) {
    entries.clear();
    if (!mip::parse_reply(p.payload, entries)) return;
    for (const auto& e : entries) {
      if (e.code == mip::ReplyCode::kAck) acked_.push_back({p.desc_set, e.cmd_desc});
    }
  });
  return !acked_.empty();
}

bool MipDeviceEmulator::acknowledged(std::uint8_t desc_set, std::uint8_t desc) const {
  for (const auto& [s, d] : acked_) {
    if (s == desc_set && d == desc) return true;
  }
  return false;
}

void MipDeviceEmulator::engine_effects(const mip::PacketView& packet, CommandEffects& effects) {
  mip::FieldWalker walker(packet.payload);
  mip::FieldView field;
  while (walker.next(field)) {
    // Only what the device accepted changes the estimate (a NACKed write has no effect).
    if (!acknowledged(packet.desc_set, field.desc)) continue;
    if (packet.desc_set == mip::set::k3dm) mounting_command(field, effects);
    if (packet.desc_set == mip::set::kFilterCmd) filter_command(field, effects);
  }
}

void MipDeviceEmulator::mounting_command(const mip::FieldView& field, CommandEffects& effects) {
  if (field.desc != mip::kSensorToVehicleEuler && field.desc != mip::kSensorToVehicleQuaternion &&
      field.desc != mip::kSensorToVehicleDcm) {
    return;
  }
  bytes::Reader<bytes::Endian::kBig> r(field.data);
  if (r.u8() != kFunctionWrite) return;
  std::optional<Eigen::Matrix3d> c_vs;
  if (field.desc == mip::kSensorToVehicleEuler) {
    const Eigen::Vector3d rpy = read_vec3f(r);
    if (r.ok()) c_vs = rot::dcm_from_rpy(rpy);
  } else {
    c_vs = mip::sensor_to_vehicle_dcm(field.desc, field.data.subspan(1));
  }
  if (!c_vs) return;
  c_vs_ = *c_vs;
  // The engine takes roll, pitch, yaw; at pitch +-90 deg the split of roll and yaw is arbitrary
  // but the rotation the same (rot::rpy_from_dcm).
  effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kMounting, rot::rpy_from_dcm(c_vs_)));
}

void MipDeviceEmulator::filter_command(const mip::FieldView& field, CommandEffects& effects) {
  bytes::Reader<bytes::Endian::kBig> r(field.data);
  switch (field.desc) {
    case kResetFilter: effects.actions.push_back(EngineAction::reset(filter::Engine::kResetFilter)); return;
    case kInitialHeading: {
      const double heading = r.f32();  // [rad], range checked by the responder
      if (r.ok()) effects.actions.push_back(EngineAction::initial_heading(heading));
      return;
    }
    case kExternalHeading:
    case kExternalHeadingWithTime: {
      // Legacy external heading (digest §6.8, L8322-8420), checked by the responder: the
      // heading of the SENSOR frame; the vehicle's is offset by the azimuth of the sensor's x
      // axis in the vehicle frame. Without a time it applies on arrival (the newest epoch).
      ExternalHeading m;
      m.header.time_ns = last_epoch_gps_ns_;
      if (field.desc == kExternalHeadingWithTime) {
        const double tow_s = r.f64();
        const std::uint16_t week = r.u16();
        m.header.time_ns = time::gps_ns_from_week_tow(week, tow_s);
      }
      const double heading = r.f32();
      m.std_rad = r.f32();
      if (!r.ok() || m.header.time_ns <= 0) return;
      m.header.time_source = TimeSource::kGps;
      m.header.valid = ExternalHeading::kValidHeading;
      m.heading_rad = rot::wrap_pi(heading - std::atan2(c_vs_(1, 0), c_vs_(0, 0)));
      effects.aiding.emplace_back(m);
      return;
    }
    default: break;
  }
  if (r.u8() != kFunctionWrite) return;
  switch (field.desc) {
    case kAntennaOffset: {
      const Eigen::Vector3d offset = read_vec3f(r);
      if (!r.ok()) return;
      gnss_lever_arm_m_ = offset;
      effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kGnssLeverArm, offset, 0));
      return;
    }
    case kSpeedLeverArm: {
      r.u8();  // source, 1 (checked by the responder)
      const Eigen::Vector3d arm = read_vec3f(r);
      if (r.ok()) effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kWheelLeverArm, arm));
      return;
    }
    case kMultiAntennaOffset: {
      const int receiver = r.u8();  // 1 primary, 2 secondary (CV7 numbering)
      const Eigen::Vector3d offset = read_vec3f(r);
      if (r.ok() && (receiver == 1 || receiver == 2)) {
        if (receiver == 1) gnss_lever_arm_m_ = offset;
        effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kGnssLeverArm, offset, receiver - 1));
      }
      return;
    }
    case kWheeledVehicle: {
      const bool enable = r.u8() != 0;
      if (r.ok()) effects.actions.push_back(EngineAction::switch_to(EngineAction::Kind::kNonholonomic, enable));
      return;
    }
    case kAidingControl: {
      const std::uint16_t source = r.u16();
      const bool enable = r.u8() != 0;
      if (!r.ok()) return;
      for (const MeasurementKind k : kinds_of_aiding_source(source)) {
        effects.actions.push_back(EngineAction::switch_to(EngineAction::Kind::kAiding, enable, k));
      }
      return;
    }
    default: return;
  }
}

}  // namespace navfuse::apps

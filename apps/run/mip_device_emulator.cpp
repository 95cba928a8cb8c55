#include "apps/run/mip_device_emulator.hpp"

#include "core/bytes/byte_reader.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"
#include "frontends/mip/commands.hpp"
#include "frontends/mip/encoder_solution.hpp"
#include "frontends/mip/packet.hpp"
#include "frontends/mip/sensor_to_vehicle.hpp"

namespace navfuse::apps {
namespace {

namespace mip = frontends::mip;

constexpr std::size_t kMaxClients = 16;  // framers kept; the oldest client's goes first
constexpr std::uint8_t kFunctionWrite = 0x01;
constexpr std::uint8_t kResetFilter = 0x01;            // (0x0D,0x01)
constexpr std::uint8_t kAntennaOffset = 0x13;          // (0x0D,0x13), the primary antenna
constexpr std::uint8_t kMultiAntennaOffset = 0x54;     // (0x0D,0x54)
constexpr std::uint8_t kSpeedLeverArm = 0x61;          // (0x0D,0x61)

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
    {0x0D, 0x03},  // set initial heading
    {0x0D, 0x15},  // GNSS aiding source
    {0x0D, 0x17},  // external heading update
    {0x0D, 0x1A},  // accel noise std
    {0x0D, 0x1B},  // gyro noise std
    {0x0D, 0x1C},  // accel bias model
    {0x0D, 0x1D},  // gyro bias model
    {0x0D, 0x1F},  // external heading update with time
    {0x0D, 0x20},  // zero angular rate update control
    {0x0D, 0x28},  // gravity noise std
    {0x0D, 0x43},  // declination source
    {0x0D, 0x50},  // aiding measurement control
    {0x0D, 0x52},  // navigation filter initialization
    {0x0D, 0x53},  // adaptive filter
    {0x0D, 0x55},  // relative position configuration
    {0x0D, 0x56},  // reference point lever arm
    {0x0D, 0x63},  // wheeled vehicle constraint
    {0x0D, 0x64},  // GNSS antenna offset calibration
};

Eigen::Vector3d read_vec3f(bytes::Reader<bytes::Endian::kBig>& r) {
  const double x = r.f32();
  const double y = r.f32();
  const double z = r.f32();
  return {x, y, z};
}

}  // namespace

MipDeviceEmulator::MipDeviceEmulator() { responder_.refuse({std::begin(kRefused), std::end(kRefused)}); }

void MipDeviceEmulator::stream(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) {
  last_epoch_gps_ns_ = epoch.solution.header.time_ns;
  if (responder_.idle() || !responder_.stream_enabled(mip::set::kFilter)) return;
  encoder_.append(epoch, out);
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

void MipDeviceEmulator::engine_effects(const mip::PacketView& packet, CommandEffects& effects) const {
  mip::FieldWalker walker(packet.payload);
  mip::FieldView field;
  while (walker.next(field)) {
    // Only what the device accepted changes the estimate (a NACKed write has no effect).
    if (!acknowledged(packet.desc_set, field.desc)) continue;
    bytes::Reader<bytes::Endian::kBig> r(field.data);
    if (packet.desc_set == mip::set::kFilterCmd && field.desc == kResetFilter) {
      effects.actions.push_back(EngineAction::reset(filter::Engine::kResetFilter));
      continue;
    }
    const bool filter = packet.desc_set == mip::set::kFilterCmd;
    const bool mounting = packet.desc_set == mip::set::k3dm &&
                          (field.desc == mip::kSensorToVehicleEuler || field.desc == mip::kSensorToVehicleQuaternion ||
                           field.desc == mip::kSensorToVehicleDcm);
    const bool antenna = filter && field.desc == kMultiAntennaOffset;
    const bool primary_antenna = filter && field.desc == kAntennaOffset;
    const bool speed_arm = filter && field.desc == kSpeedLeverArm;
    if ((!mounting && !antenna && !primary_antenna && !speed_arm) || r.u8() != kFunctionWrite) continue;
    if (mounting && field.desc == mip::kSensorToVehicleEuler) {
      const Eigen::Vector3d rpy = read_vec3f(r);
      if (r.ok()) effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kMounting, rpy));
    } else if (mounting) {
      // The engine takes roll, pitch, yaw; at pitch +-90 deg the split of roll and yaw is
      // arbitrary but the rotation the same (rot::rpy_from_dcm).
      if (const auto c = mip::sensor_to_vehicle_dcm(field.desc, field.data.subspan(1))) {
        effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kMounting, rot::rpy_from_dcm(*c)));
      }
    } else if (primary_antenna) {
      const Eigen::Vector3d offset = read_vec3f(r);
      if (r.ok()) effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kGnssLeverArm, offset, 0));
    } else if (speed_arm) {
      r.u8();  // source, 1 (checked by the responder)
      const Eigen::Vector3d arm = read_vec3f(r);
      if (r.ok()) effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kWheelLeverArm, arm));
    } else {
      const int receiver = r.u8();  // 1 primary, 2 secondary (CV7 numbering)
      const Eigen::Vector3d offset = read_vec3f(r);
      if (r.ok() && (receiver == 1 || receiver == 2)) {
        effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kGnssLeverArm, offset, receiver - 1));
      }
    }
  }
}

}  // namespace navfuse::apps

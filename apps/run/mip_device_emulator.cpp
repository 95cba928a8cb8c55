#include "apps/run/mip_device_emulator.hpp"

#include "core/bytes/byte_reader.hpp"
#include "filter/engine.hpp"
#include "frontends/mip/commands.hpp"
#include "frontends/mip/encoder_solution.hpp"
#include "frontends/mip/packet.hpp"

namespace navfuse::apps {
namespace {

namespace mip = frontends::mip;

constexpr std::size_t kMaxClients = 16;  // framers kept; the oldest client's goes first
constexpr std::uint8_t kFunctionWrite = 0x01;
constexpr std::uint8_t kResetFilter = 0x01;            // (0x0D,0x01)
constexpr std::uint8_t kSensorToVehicleEuler = 0x31;   // (0x0C,0x31)
constexpr std::uint8_t kMultiAntennaOffset = 0x54;     // (0x0D,0x54)

Eigen::Vector3d read_vec3f(bytes::Reader<bytes::Endian::kBig>& r) {
  const double x = r.f32();
  const double y = r.f32();
  const double z = r.f32();
  return {x, y, z};
}

}  // namespace

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
    const bool mounting = packet.desc_set == mip::set::k3dm && field.desc == kSensorToVehicleEuler;
    const bool antenna = packet.desc_set == mip::set::kFilterCmd && field.desc == kMultiAntennaOffset;
    if ((!mounting && !antenna) || r.u8() != kFunctionWrite) continue;
    if (mounting) {
      const Eigen::Vector3d rpy = read_vec3f(r);
      if (r.ok()) effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kMounting, rpy));
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

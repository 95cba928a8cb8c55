#include "apps/run/fe_device_emulator.hpp"

#include "apps/output/fe_pose_writer.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"
#include "frontends/fusionengine/payload_reader.hpp"

namespace navfuse::apps {
namespace {

namespace fe = frontends::fusionengine;

using fe::MessageRate;
using fe::MessageType;

constexpr std::size_t kMaxClients = 16;  // framers kept; the oldest client's goes first

// Period of an interval rate (spec L1419-1440), 0 for the others.
double period_s(MessageRate rate) {
  switch (rate) {
    case MessageRate::k10Ms: return 0.01;
    case MessageRate::k20Ms: return 0.02;
    case MessageRate::k40Ms: return 0.04;
    case MessageRate::k50Ms: return 0.05;
    case MessageRate::k100Ms: return 0.1;
    case MessageRate::k200Ms: return 0.2;
    case MessageRate::k500Ms: return 0.5;
    case MessageRate::k1S: return 1.0;
    case MessageRate::k2S: return 2.0;
    case MessageRate::k5S: return 5.0;
    case MessageRate::k10S: return 10.0;
    case MessageRate::k30S: return 30.0;
    case MessageRate::k60S: return 60.0;
    default: return 0.0;
  }
}

bool is_known_rate(std::uint8_t r) { return r <= static_cast<std::uint8_t>(MessageRate::k60S) || r == 0xFF; }

template <class M>
bool parse(const fe::Frame& frame, M& out) {
  fe::PayloadReader r(frame.payload);
  out.visit(r);
  return r.ok();
}

// FusionEngine ResetRequest bits -> what the engine can reset (spec L719-798). GNSS-receiver
// state (corrections, ephemeris, time) has no counterpart in a filter fed by a receiver.
std::uint32_t engine_reset_mask(std::uint32_t fe_mask) {
  namespace reset = fe::reset;
  std::uint32_t mask = 0;
  if (fe_mask & (reset::kRestartNavigationEngine | reset::kResetNavigationEngineData |
                 reset::kRebootNavigationProcessor)) {
    mask |= filter::Engine::kResetFilter;
  }
  if (fe_mask & reset::kResetPositionData) mask |= filter::Engine::kResetPosition;
  if (fe_mask & (reset::kResetFastImuCorrections | reset::kResetCalibrationData)) mask |= filter::Engine::kResetBiases;
  return mask;
}

// What a SetConfig (or a revert by SaveConfig) changed, as engine actions. Lever arms and
// mounting are the settings the engine takes live (filter::Engine::set_gnss_lever_arm,
// set_mounting); config lever arms are vehicle FRD metres, mounting 3-2-1 degrees.
void config_changes_to_actions(const config::Config& before, const config::Config& after, CommandEffects& effects) {
  const auto vec = [](const config::Vec3& v) { return Eigen::Vector3d(v[0], v[1], v[2]); };
  if (after.gnss.lever_arm_m != before.gnss.lever_arm_m) {
    effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kGnssLeverArm, vec(after.gnss.lever_arm_m), 0));
  }
  if (after.gnss.secondary_lever_arm_m != before.gnss.secondary_lever_arm_m) {
    effects.actions.push_back(
        EngineAction::with_vector(EngineAction::Kind::kGnssLeverArm, vec(after.gnss.secondary_lever_arm_m), 1));
  }
  if (after.imu.mounting_rpy_deg != before.imu.mounting_rpy_deg) {
    effects.actions.push_back(EngineAction::with_vector(EngineAction::Kind::kMounting,
                                                        vec(after.imu.mounting_rpy_deg) * rot::kDegToRad));
  }
}

}  // namespace

// ---- FeStreamRates ---------------------------------------------------------------------------

FeStreamRates::FeStreamRates()
    : entries_{{{MessageType::kPose}, {MessageType::kPoseAux}, {MessageType::kGnssInfo}, {MessageType::kImuOutput}}} {}

FeStreamRates::Entry* FeStreamRates::find(MessageType type) {
  for (Entry& e : entries_) {
    if (e.type == type) return &e;
  }
  return nullptr;
}

fe::MessageRate FeStreamRates::rate(MessageType type) const {
  for (const Entry& e : entries_) {
    if (e.type == type) return e.rate;
  }
  return MessageRate::kOff;
}

bool FeStreamRates::set(std::uint16_t message_id, MessageRate rate) {
  const auto apply = [rate](Entry& e) {
    e.rate = rate;
    const double p = period_s(rate);
    e.interval = OutputRate(p > 0 ? 1.0 / p : 0.0);
  };
  if (message_id == fe::kAllMessages) {
    for (Entry& e : entries_) apply(e);
    return true;
  }
  Entry* e = find(static_cast<MessageType>(message_id));
  if (e == nullptr) return false;
  apply(*e);
  return true;
}

bool FeStreamRates::due(MessageType type, std::int64_t time_ns, bool default_due, bool on_change) {
  Entry* e = find(type);
  if (e == nullptr) return false;
  switch (e->rate) {
    case MessageRate::kOff: return false;
    case MessageRate::kDefault: return default_due;
    case MessageRate::kOnChange: return on_change;
    default: return e->interval.due(time_ns);
  }
}

// ---- FeDeviceEmulator ------------------------------------------------------------------------

FeDeviceEmulator::FeDeviceEmulator(const config::Config& config) : config_(config), control_(config) {}

void FeDeviceEmulator::stream(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) {
  last_ = epoch;
  have_last_ = true;
  const NavSolution& s = epoch.solution;
  const std::int64_t t = s.header.time_ns;
  const bool gnss_changed = epoch.gnss_fused_total != gnss_at_last_info_;
  // Defaults (DESIGN.md --fe-out): poses at output.rate_hz, GNSSInfo at pose times after a fix,
  // IMUOutput after every IMU sample.
  if (rates_.due(MessageType::kPose, t, epoch.pose_due, true)) {
    const auto& b = writer_.pose(s);
    out.insert(out.end(), b.begin(), b.end());
  }
  if (rates_.due(MessageType::kPoseAux, t, epoch.pose_due, true)) {
    const auto& b = writer_.pose_aux(s);
    out.insert(out.end(), b.begin(), b.end());
  }
  if (rates_.due(MessageType::kGnssInfo, t, epoch.pose_due && gnss_changed, gnss_changed)) {
    gnss_at_last_info_ = epoch.gnss_fused_total;
    const auto& b = writer_.gnss_info(s, epoch.num_sats);
    out.insert(out.end(), b.begin(), b.end());
  }
  if (rates_.due(MessageType::kImuOutput, t, true, true) && compensated_imu_from(s, imu_)) {
    const auto& b = writer_.imu_output(imu_);
    out.insert(out.end(), b.begin(), b.end());
  }
}

fe::Framer& FeDeviceEmulator::framer_for(io::PeerId peer) {
  auto it = framers_.find(peer);
  if (it != framers_.end()) return *it->second;
  // Peer ids only grow, so the smallest belongs to the client that connected first.
  if (framers_.size() >= kMaxClients) framers_.erase(framers_.begin());
  return *framers_.emplace(peer, std::make_unique<fe::Framer>()).first->second;
}

void FeDeviceEmulator::receive(io::PeerId peer, std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& reply,
                               CommandEffects& effects) {
  framer_for(peer).feed(bytes, [&](const fe::Frame& frame) { handle(frame, reply, effects); });
}

void FeDeviceEmulator::handle(const fe::Frame& frame, std::vector<std::uint8_t>& reply, CommandEffects& effects) {
  const auto answer = [&](fe::Response code) {
    const auto& b = writer_.command_response(frame.header.sequence, code);
    reply.insert(reply.end(), b.begin(), b.end());
  };
  switch (static_cast<MessageType>(frame.header.message_type)) {
    case MessageType::kSetMessageRate: {
      fe::SetMessageRateMessage m;
      if (!parse(frame, m)) return answer(fe::Response::kInconsistentPayloadLength);
      const auto protocol = static_cast<fe::ProtocolType>(m.protocol);
      if ((protocol != fe::ProtocolType::kFusionEngine && protocol != fe::ProtocolType::kAll) || !is_known_rate(m.rate)) {
        return answer(fe::Response::kValueError);
      }
      const bool ok = rates_.set(m.message_id, static_cast<MessageRate>(m.rate));
      return answer(ok ? fe::Response::kOk : fe::Response::kUnsupportedFeature);
    }
    case MessageType::kGetMessageRate: {
      fe::GetMessageRateMessage m;
      if (!parse(frame, m)) return answer(fe::Response::kInconsistentPayloadLength);
      fe::MessageRateResponseMessage r;
      r.source = m.source;
      r.output_interface = m.output_interface;
      for (const auto& e : rates_.entries()) {
        if (m.message_id != fe::kAllMessages && m.message_id != fe::to_u16(e.type)) continue;
        fe::MessageRateEntry entry;
        entry.protocol = static_cast<std::uint8_t>(fe::ProtocolType::kFusionEngine);
        entry.message_id = fe::to_u16(e.type);
        entry.configured_rate = static_cast<std::uint8_t>(e.rate);
        entry.effective_rate = static_cast<std::uint8_t>(e.rate);
        r.rates.push_back(entry);
      }
      r.response = static_cast<std::uint8_t>(r.rates.empty() ? fe::Response::kUnsupportedFeature : fe::Response::kOk);
      writer_.append(std::move(r), reply);
      return;
    }
    case MessageType::kMessageRequest: {
      fe::MessageRequestMessage m;
      if (!parse(frame, m)) return answer(fe::Response::kInconsistentPayloadLength);
      if (!have_last_) return answer(fe::Response::kNoDataStored);
      const NavSolution& s = last_.solution;
      switch (static_cast<MessageType>(m.message_type)) {
        case MessageType::kPose: writer_.append(fe::pose_from(s), reply); return;
        case MessageType::kPoseAux: writer_.append(fe::pose_aux_from(s), reply); return;
        case MessageType::kGnssInfo: writer_.append(fe::gnss_info_from(s, last_.num_sats), reply); return;
        default: return answer(fe::Response::kUnsupportedFeature);
      }
    }
    case MessageType::kResetRequest: {
      fe::ResetRequestMessage m;
      if (!parse(frame, m)) return answer(fe::Response::kInconsistentPayloadLength);
      const std::uint32_t mask = engine_reset_mask(m.reset_mask);
      if (mask != 0) effects.actions.push_back(EngineAction::reset(mask));
      return answer(fe::Response::kOk);
    }
    case MessageType::kSetConfig:
    case MessageType::kGetConfig:
    case MessageType::kSaveConfig: {
      const config::Config before = control_.config();
      control_.feed(frame.bytes, reply);
      config_changes_to_actions(before, control_.config(), effects);
      return;
    }
    case MessageType::kShutdownRequest:
    case MessageType::kStartupRequest:
    case MessageType::kFaultControl:
    case MessageType::kImportData:
    case MessageType::kExportData:
      // Commands a device answers but this link does not implement: say so rather than leave
      // the client waiting for a response that never comes.
      return answer(fe::Response::kUnsupportedFeature);
    default:
      return;  // not a command: a client's own stream (e.g. echoed output) is not answered
  }
}

std::unique_ptr<DeviceEmulator> make_fe_device_emulator(const config::Config& config) {
  return std::make_unique<FeDeviceEmulator>(config);
}

}  // namespace navfuse::apps

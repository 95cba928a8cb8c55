#include "apps/run/fe_device_emulator.hpp"

#include "apps/run/arrived_measurement.hpp"
#include "apps/run/run_log.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"
#include "frontends/fusionengine/payload_reader.hpp"

namespace navfuse::apps {
namespace {

namespace fe = frontends::fusionengine;

using fe::MessageRate;
using fe::MessageType;

constexpr std::size_t kMaxClients = 16;  // framers kept; the oldest client's goes first

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

FeDeviceEmulator::FeDeviceEmulator(const config::Config& config, bool device_link)
    : config_(config), control_(config, FeDeviceStatus::versions()), device_link_(device_link), status_(config) {}

void FeDeviceEmulator::stream(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) {
  last_ = epoch;
  have_last_ = true;
  const NavSolution& s = epoch.solution;
  status_.update(s);
  inputs_.set_now_ns(s.header.time_ns);
  encoder_.append(epoch, out);
  if (!device_link_) return;
  announce_restarts(epoch);
  auto& writer = encoder_.writer();
  for (auto& e : pending_events_) writer.append(std::move(e), out);
  pending_events_.clear();
  // Both interval clocks run every epoch so that a default rate restored later stays on its grid.
  const std::int64_t t = s.header.time_ns;
  const bool calibration_default = calibration_default_.due(t);
  const bool system_default = system_default_.due(t);
  if (encoder_.rates().due(MessageType::kCalibrationStatus, t, calibration_default, true)) {
    writer.append(status_.calibration(s), out);
  }
  if (encoder_.rates().due(MessageType::kSystemStatus, t, system_default, true)) writer.append(status_.system(s), out);
}

void FeDeviceEmulator::announce_restarts(const OutputEpoch& epoch) {
  // A restart of the filter's own clears its position, velocity, attitude and IMU corrections:
  // what RESET_NAVIGATION_ENGINE_DATA resets on a device (spec L743), reported with the flags
  // a ResetRequest of that mask would carry (L2639).
  const auto announce = [&](std::uint64_t count, std::uint64_t& seen, const char* cause) {
    if (count <= seen) return;
    seen = count;
    pending_events_.push_back(FeDeviceStatus::event(fe::EventType::kReset, fe::reset::kResetNavigationEngineData,
                                                    std::string("filter restarted: ") + cause, monotonic_ns()));
  };
  announce(epoch.time_gap_restarts, time_gap_restarts_seen_, "IMU time gap beyond max_imu_gap_s");
  announce(epoch.divergence_restarts, divergence_restarts_seen_, "diverged");
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
    const auto& b = encoder_.writer().command_response(frame.header.sequence, code);
    reply.insert(reply.end(), b.begin(), b.end());
  };
  switch (static_cast<MessageType>(frame.header.message_type)) {
    case MessageType::kSetMessageRate: {
      fe::SetMessageRateMessage m;
      if (!parse(frame, m)) return answer(fe::Response::kInconsistentPayloadLength);
      const auto protocol = static_cast<fe::ProtocolType>(m.protocol);
      if ((protocol != fe::ProtocolType::kFusionEngine && protocol != fe::ProtocolType::kAll) || !fe::valid_rate(m.rate)) {
        return answer(fe::Response::kValueError);
      }
      const bool ok = encoder_.rates().set(m.message_id, static_cast<MessageRate>(m.rate),
                                           (m.flags & fe::kRateFlagIncludeDisabled) != 0,
                                           (m.flags & fe::kRateFlagApplyAndSave) != 0);
      return answer(ok ? fe::Response::kOk : fe::Response::kUnsupportedFeature);
    }
    case MessageType::kGetMessageRate: {
      fe::GetMessageRateMessage m;
      if (!parse(frame, m)) return answer(fe::Response::kInconsistentPayloadLength);
      fe::MessageRateResponseMessage r;
      r.source = m.source;
      r.output_interface = m.output_interface;
      const auto source = static_cast<fe::ConfigSource>(m.source);
      if (source != fe::ConfigSource::kActive && source != fe::ConfigSource::kSaved &&
          source != fe::ConfigSource::kDefault) {
        r.response = static_cast<std::uint8_t>(fe::Response::kValueError);
        encoder_.writer().append(std::move(r), reply);
        return;
      }
      for (const auto& e : encoder_.rates().entries()) {
        if (m.message_id != fe::kAllMessages && m.message_id != fe::to_u16(e.type)) continue;
        fe::MessageRateEntry entry;
        entry.protocol = static_cast<std::uint8_t>(fe::ProtocolType::kFusionEngine);
        entry.flags = e.rate != e.saved ? fe::kRateEntryActiveDiffersFromSaved : 0;
        entry.message_id = fe::to_u16(e.type);
        const MessageRate configured = source == fe::ConfigSource::kActive  ? e.rate
                                       : source == fe::ConfigSource::kSaved ? e.saved
                                                                            : MessageRate::kDefault;
        entry.configured_rate = static_cast<std::uint8_t>(configured);
        // The rate the stream uses now, whichever copy was asked for (L1679).
        entry.effective_rate = static_cast<std::uint8_t>(e.rate);
        r.rates.push_back(entry);
      }
      r.response = static_cast<std::uint8_t>(r.rates.empty() ? fe::Response::kUnsupportedFeature : fe::Response::kOk);
      encoder_.writer().append(std::move(r), reply);
      return;
    }
    case MessageType::kMessageRequest: {
      fe::MessageRequestMessage m;
      if (!parse(frame, m)) return answer(fe::Response::kInconsistentPayloadLength);
      if (m.message_type == fe::to_u16(MessageType::kVersionInfo)) {
        control_.respond(frame, encoder_.writer(), reply);
        return;
      }
      if (!have_last_) return answer(fe::Response::kNoDataStored);
      const NavSolution& s = last_.solution;
      auto& writer = encoder_.writer();
      switch (static_cast<MessageType>(m.message_type)) {
        case MessageType::kPose: writer.append(fe::pose_from(s), reply); return;
        case MessageType::kPoseAux: writer.append(fe::pose_aux_from(s), reply); return;
        case MessageType::kGnssInfo: writer.append(fe::gnss_info_from(s, last_.num_sats), reply); return;
        case MessageType::kCalibrationStatus: writer.append(status_.calibration(s), reply); return;
        case MessageType::kSystemStatus: writer.append(status_.system(s), reply); return;
        default: return answer(fe::Response::kUnsupportedFeature);
      }
    }
    case MessageType::kResetRequest: {
      fe::ResetRequestMessage m;
      if (!parse(frame, m)) return answer(fe::Response::kInconsistentPayloadLength);
      const std::uint32_t mask = engine_reset_mask(m.reset_mask);
      if (mask != 0) {
        effects.actions.push_back(EngineAction::reset(mask));
        // "The event flags will be set to the requested reset bitmask" (L2639).
        pending_events_.push_back(FeDeviceStatus::event(fe::EventType::kReset, m.reset_mask,
                                                        "ResetRequest from a client", monotonic_ns()));
      }
      // RESET_CONFIG restores the factory configuration, rates included: the device control
      // answers and resets the settings, the stream's rate table is reset here.
      if ((m.reset_mask & fe::reset::kResetConfig) != 0) encoder_.rates().revert_to_default();
      return configure(frame, reply, effects);
    }
    case MessageType::kSaveConfig: {
      // The rates are part of "the active configuration" SaveConfig saves or reverts (L1336-1377).
      fe::SaveConfigMessage m;
      if (parse(frame, m)) {
        switch (static_cast<fe::SaveAction>(m.action)) {
          case fe::SaveAction::kSave: encoder_.rates().save(); break;
          case fe::SaveAction::kRevertToSaved: encoder_.rates().revert_to_saved(); break;
          case fe::SaveAction::kRevertToDefault: encoder_.rates().revert_to_default(); break;
          default: break;  // the device control answers Value Error
        }
      }
      return configure(frame, reply, effects);
    }
    case MessageType::kSetConfig:
    case MessageType::kGetConfig: return configure(frame, reply, effects);
    case MessageType::kShutdownRequest:
    case MessageType::kStartupRequest:
    case MessageType::kFaultControl:
    case MessageType::kImportData:
    case MessageType::kExportData:
      // Commands a device answers but this link does not implement: say so rather than leave
      // the client waiting for a response that never comes.
      return answer(fe::Response::kUnsupportedFeature);
    default:
      // Sensor inputs are fused; anything else that is not a command (e.g. echoed output) is
      // neither answered nor used.
      if (inputs_.decode(frame, effects.aiding) && inputs_.decode_errors() > input_errors_logged_) {
        // Reported as they first happen and then at each power of ten: a client that keeps
        // sending a wrong layout does not flood the log.
        const std::uint64_t n = inputs_.decode_errors();
        if (n >= 10 * input_errors_logged_) {
          log_event("--fe-out: sensor input (type " + std::to_string(frame.header.message_type) +
                    ") shorter than its layout, dropped (" + std::to_string(n) + " so far)");
          input_errors_logged_ = n;
        }
      }
      return;
  }
}

void FeDeviceEmulator::configure(const fe::Frame& frame, std::vector<std::uint8_t>& reply, CommandEffects& effects) {
  const config::Config before = control_.config();
  const std::uint64_t changes = control_.config_changes();
  control_.respond(frame, encoder_.writer(), reply);
  config_changes_to_actions(before, control_.config(), effects);
  inputs_.set_wheel_config(control_.wheel_config());
  if (control_.config_changes() != changes) {
    pending_events_.push_back(FeDeviceStatus::event(fe::EventType::kConfigChange, 0,
                                                    "configuration changed by a client", monotonic_ns()));
  }
}

std::unique_ptr<DeviceEmulator> make_fe_device_emulator(const config::Config& config, bool device_link) {
  return std::make_unique<FeDeviceEmulator>(config, device_link);
}

}  // namespace navfuse::apps

// --fe-out: navfuse as a Point One FusionEngine device on the link. Streams what replay's
// --fe-out file holds (apps/output/fe_epoch_encoder.hpp: IMUOutput, Pose, PoseAux, GNSSInfo)
// and, as a device does, CalibrationStatus and SystemStatus (1 s by default, as a Point One
// device streams them) and EventNotifications for the resets and
// configuration changes its clients cause and the filter restarts it makes on its own (IMU time
// gap, divergence; apps/run/fe_device_status.hpp); each message at the
// rate a client set with SetMessageRate. It answers the device's commands on the same link
// (configuration commands and VersionInfo through frontends/fusionengine/responder.hpp). All of
// it, responses included, carries one sequence counter (spec L190: the stream's).
// On a file (run --fe-out file:F) nobody can send a command or hear about the device: the
// stream is then exactly what replay writes to its --fe-out file (run --record, then replay,
// gives the same bytes), without the status messages.
#pragma once

#include <map>
#include <memory>

#include "apps/output/fe_epoch_encoder.hpp"
#include "apps/run/device_emulator.hpp"
#include "apps/run/fe_device_status.hpp"
#include "apps/run/fe_link_inputs.hpp"
#include "core/config/config.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/messages_control.hpp"
#include "frontends/fusionengine/responder.hpp"

namespace navfuse::apps {

class FeDeviceEmulator final : public DeviceEmulator {
 public:
  // `device_link`: a link a client talks on (serial, TCP, UDP), not a file.
  FeDeviceEmulator(const config::Config& config, bool device_link);
  std::string_view protocol() const override { return "fe"; }
  void stream(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) override;
  void receive(io::PeerId peer, std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& reply,
               CommandEffects& effects) override;

 private:
  void handle(const frontends::fusionengine::Frame& frame, std::vector<std::uint8_t>& reply, CommandEffects& effects);
  // A command the device control answers (configuration, save/revert, reset); what it changed
  // in the config becomes engine actions and a CONFIG_CHANGE event.
  void configure(const frontends::fusionengine::Frame& frame, std::vector<std::uint8_t>& reply, CommandEffects& effects);
  frontends::fusionengine::Framer& framer_for(io::PeerId peer);
  // Queues a RESET event for each restart the filter made on its own since the last epoch.
  void announce_restarts(const OutputEpoch& epoch);

  config::Config config_;
  // SetConfig / GetConfig / SaveConfig are answered by the front-end's device-compatible
  // handler; what it changes in the config is handed to the engine as EngineActions.
  frontends::fusionengine::DeviceControl control_;
  FeEpochEncoder encoder_;  // its writer: one sequence counter for everything this link sends
  std::map<io::PeerId, std::unique_ptr<frontends::fusionengine::Framer>> framers_;
  OutputEpoch last_;  // for MessageRequest: the newest solution
  bool have_last_ = false;
  bool device_link_;
  FeDeviceStatus status_;
  FeLinkInputs inputs_;  // sensor inputs clients send, fused as from an --in FusionEngine stream
  std::uint64_t input_errors_logged_ = 0;
  OutputRate calibration_default_{1.0}, system_default_{1.0};  // Hz, the device defaults
  // Events of the commands since the last epoch: they go to every client, with the stream.
  std::vector<frontends::fusionengine::EventNotificationMessage> pending_events_;
  std::uint64_t time_gap_restarts_seen_ = 0, divergence_restarts_seen_ = 0;
};

std::unique_ptr<DeviceEmulator> make_fe_device_emulator(const config::Config& config, bool device_link = true);

}  // namespace navfuse::apps

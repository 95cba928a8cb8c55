// --fe-out: navfuse as a Point One FusionEngine device on the link. Streams Pose (10000) and
// PoseAux (10003) at output.rate_hz, GNSSInfo (10001) at pose times after a GNSS fix was fused,
// and IMUOutput (11000) after every IMU sample (DESIGN.md --fe-out), each at the rate a client
// set with SetMessageRate; and answers the device's commands on the same link (configuration
// commands through frontends/fusionengine/responder).
#pragma once

#include <array>
#include <map>
#include <memory>

#include "apps/output/output_rate.hpp"
#include "apps/run/device_emulator.hpp"
#include "core/config/config.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/messages_control.hpp"
#include "frontends/fusionengine/responder.hpp"
#include "frontends/fusionengine/writer.hpp"

namespace navfuse::apps {

// The messages navfuse streams, with their current rates.
class FeStreamRates {
 public:
  struct Entry {
    frontends::fusionengine::MessageType type;
    frontends::fusionengine::MessageRate rate = frontends::fusionengine::MessageRate::kDefault;
    OutputRate interval{0.0};  // for interval rates (k10Ms ... k60S)
  };
  FeStreamRates();

  // False for a message navfuse does not stream (the device answers "unsupported").
  bool set(std::uint16_t message_id, frontends::fusionengine::MessageRate rate);
  frontends::fusionengine::MessageRate rate(frontends::fusionengine::MessageType type) const;
  // Whether `type` goes out at this epoch. `default_due` is when it would at its default rate,
  // `on_change` whether its content changed since it last went out.
  bool due(frontends::fusionengine::MessageType type, std::int64_t time_ns, bool default_due, bool on_change);
  const std::array<Entry, 4>& entries() const { return entries_; }

 private:
  Entry* find(frontends::fusionengine::MessageType type);
  std::array<Entry, 4> entries_;
};

class FeDeviceEmulator final : public DeviceEmulator {
 public:
  explicit FeDeviceEmulator(const config::Config& config);
  std::string_view protocol() const override { return "fe"; }
  void stream(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) override;
  void receive(io::PeerId peer, std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& reply,
               CommandEffects& effects) override;

 private:
  void handle(const frontends::fusionengine::Frame& frame, std::vector<std::uint8_t>& reply, CommandEffects& effects);
  frontends::fusionengine::Framer& framer_for(io::PeerId peer);

  config::Config config_;
  // SetConfig / GetConfig / SaveConfig are answered by the front-end's device-compatible
  // handler; what it changes in the config is handed to the engine as EngineActions.
  frontends::fusionengine::DeviceControl control_;
  FeStreamRates rates_;
  frontends::fusionengine::FusionEngineWriter writer_;  // one sequence counter for everything this link sends
  std::map<io::PeerId, std::unique_ptr<frontends::fusionengine::Framer>> framers_;
  OutputEpoch last_;  // for MessageRequest: the newest solution
  bool have_last_ = false;
  std::uint64_t gnss_at_last_info_ = 0;
  ImuSample imu_;  // reused
};

std::unique_ptr<DeviceEmulator> make_fe_device_emulator(const config::Config& config);

}  // namespace navfuse::apps

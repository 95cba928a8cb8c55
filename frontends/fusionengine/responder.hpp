// Device-compatible FusionEngine command handling for the nav process: answers commands the
// way a Point One device does (spec §3.1-3.2), against core types only.
//
//   SetConfig    lever arms (GNSS 0x12, GNSS aux 0x18) and device orientation (0x11) change the
//                navfuse::config::Config; device/output lever arms (0x10/0x13), vehicle details
//                (0x14) and wheel config (0x15) are kept here -> CommandResponse
//   GetConfig    reports the active / saved / default value -> ConfigResponse
//   SaveConfig   save, revert to saved, revert to default -> CommandResponse
//   SetMessageRate / GetMessageRate   not here: the rates belong to the stream that applies them
//                (apps/output/fe_stream_rates.hpp, answered by the --fe-out link) -> Unsupported
//                Feature from this handler alone
//   ResetRequest records "reset requested with mask M" (RESET_CONFIG also restores defaults)
//                -> CommandResponse
//   MessageRequest  VersionInfo (13003) -> VersionInfo; other types -> CommandResponse Value Error
// Any other command gets Unsupported Feature, a payload too short for its layout Inconsistent
// Payload Length (Response codes, spec L1579-1590); nothing in a request can crash it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/config/config.hpp"
#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/message_catalog.hpp"
#include "frontends/fusionengine/writer.hpp"

namespace navfuse::frontends::fusionengine {

// Strings reported in VersionInfo (spec §3.7.3).
struct VersionStrings {
  std::string firmware = "navfuse 0.1.0";
  std::string engine = "1.25.0";  // FusionEngine protocol release the front-end implements
  std::string os;
  std::string receiver;
};

class DeviceControl {
 public:
  explicit DeviceControl(const config::Config& config, VersionStrings versions = {});

  // Feeds command bytes (any chunking) and appends the response frames to `responses`, framed
  // by this handler's own writer (a stream of nothing but responses).
  void feed(std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& responses);
  // Answers one framed command with `writer`, the writer of the stream the answer goes out on:
  // "A sequence number that is incremented with each message" (spec L190) is one counter per
  // stream, so a device link's responses must not carry a second counter beside its outputs'.
  void respond(const Frame& frame, FusionEngineWriter& writer, std::vector<std::uint8_t>& out);

  const config::Config& config() const { return active_.config; }
  // The active WheelConfig (0x15): how the wheel inputs a client sends are to be read.
  const WheelConfig& wheel_config() const { return active_.wheel; }
  // The reset mask of the last ResetRequest not yet taken (then cleared): the nav process resets
  // its filter per the mask (reset:: bits in messages_control.hpp).
  std::optional<std::uint32_t> take_reset_request() {
    auto m = reset_request_;
    reset_request_.reset();
    return m;
  }
  const frontends::StreamCounters& counters() const { return framer_.counters(); }
  // Counts the commands that changed the active configuration (lever arms, orientation, vehicle,
  // wheel config), for CONFIG_CHANGE event notifications (spec L2640).
  std::uint64_t config_changes() const { return config_changes_; }

 private:
  // Everything a SetConfig changes; three copies: active, saved, default.
  struct State {
    config::Config config;
    Point3f device_lever_arm;
    Point3f output_lever_arm;
    VehicleDetails vehicle;
    WheelConfig wheel;
    bool operator==(const State&) const;
  };

  void on_frame(const Frame& f, FusionEngineWriter& writer, std::vector<std::uint8_t>& out);
  Response set_config(const SetConfigMessage& m);
  std::optional<std::vector<std::uint8_t>> config_value(const State& s, std::uint16_t type) const;
  Response apply_config_value(State& s, std::uint16_t type, std::span<const std::uint8_t> value) const;
  const State& state_for(std::uint8_t source) const;

  State active_, saved_, default_;
  VersionStrings versions_;
  std::optional<std::uint32_t> reset_request_;
  std::uint64_t config_changes_ = 0;
  Framer framer_;
  MessageSet messages_;
  FusionEngineWriter writer_;
};

}  // namespace navfuse::frontends::fusionengine

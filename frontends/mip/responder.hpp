// Answers MIP command packets as a CV7 would, so software written for a CV7 can configure and
// talk to navfuse (issue #4): one ACK/NACK field per command, in order, each followed by its
// response data when the command is a read (digest §2.5, L3848-3893; response map §7.7).
//
// Settings commands (those with a function selector, digest §2.6) are remembered per key
// (e.g. per descriptor set for the message format): Write stores, Read returns what was written
// (zeros before any write), Default forgets, Save/Load are acknowledged. Aiding (0x13) goes to an
// AidingCommandHandler whose measurements are handed back. Unknown descriptors are NACKed
// "unknown command", a bad checksum "bad checksum", a set without commands "unknown descriptor set".
// A sensor-to-vehicle quaternion or DCM that is no rotation is NACKed "invalid parameter"
// (frontends/mip/sensor_to_vehicle.hpp), an antenna offset or reference-point lever arm longer
// than the documented 10 m likewise. Commands the owner cannot carry out (refuse()) are
// NACKed "command failed" rather than acknowledged and ignored.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/measurements/measurements.hpp"
#include "frontends/mip/aiding.hpp"

namespace navfuse::frontends::mip {

struct DeviceIdentity {
  std::uint16_t firmware_version = 1;
  std::string model_name = "navfuse";
  std::string model_number = "3DM-CV7-GNSS/INS";
  std::string serial_number = "0";
  std::string lot_number = "";
  std::string device_options = "";
};

class CommandResponder {
 public:
  explicit CommandResponder(DeviceIdentity identity = {}, const time::ClockModel* clock = nullptr);
  // Handles one whole packet; `reply` receives the reply packet(s) (empty for data packets or
  // suppressed aiding ACKs), `aiding` the accepted aiding measurements.
  void handle_packet(std::span<const std::uint8_t> packet, std::vector<std::uint8_t>& reply,
                     std::vector<Measurement>& aiding, std::int64_t arrival_gps_ns = 0);

  // (set, descriptor) of documented commands the device cannot carry out: a Write of such a
  // setting, or such an action, is answered "command failed" (0x04, digest L8873-8881); Read,
  // Save, Load and Default still work (they change nothing the device does).
  void refuse(std::vector<std::pair<std::uint8_t, std::uint8_t>> commands) { refused_ = std::move(commands); }

  bool idle() const { return idle_; }
  // Stream control (0x0C,0x11); all streams are enabled by default (L6898-6913).
  bool stream_enabled(std::uint8_t data_set) const;
  const AidingCommandHandler& aiding_handler() const { return aiding_; }

 private:
  ReplyCode handle_command(std::uint8_t desc_set, std::uint8_t desc, std::span<const std::uint8_t> data,
                           std::vector<std::uint8_t>& response);

  DeviceIdentity identity_;
  AidingCommandHandler aiding_;
  bool idle_ = false;
  std::map<std::uint8_t, bool> streams_;
  // Key: set, descriptor and up to 4 key-parameter bytes packed in an integer. Value: the
  // written parameters after the key.
  std::map<std::uint64_t, std::vector<std::uint8_t>> settings_;
  std::vector<std::pair<std::uint8_t, std::uint8_t>> refused_;
};

}  // namespace navfuse::frontends::mip

// External aiding over MIP set 0x13, answered as a CV7 would (digest §5, spec L720-851,
// L2352-2454, L7721-8000): the frame configuration (0x13,0x01), echo control (0x13,0x1F) and every
// aiding measurement (0x21 ECEF position, 0x22 LLH position, 0x23 height, 0x28 ECEF velocity,
// 0x29 NED velocity, 0x2A body-frame velocity, 0x31 true heading, 0x32 magnetic field,
// 0x33 pressure) become core measurements in the vehicle frame, and every command gets its
// ACK/NACK field (plus response data for reads) in the reply packet.
//
// Rules applied (digest §5.4): a valid axis needs a finite value and an uncertainty > 0, else
// the command is NACKed "invalid parameter" (L783, L7829); axes whose valid bit is 0 are ignored
// (L7830); frame_id 0 is the device itself, 1..4 must have been configured (L7755, errata E8),
// anything else is NACKed "invalid parameter".
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/measurements/measurements.hpp"
#include "core/time/clock_model.hpp"
#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {

// One aiding frame: p_vehicle = R * p_sensor + t (digest §5.2, [EXT-SDK] form of L7750).
struct AidingFrame {
  bool configured = false;
  std::uint8_t format = 1;        // 1 Euler, 2 quaternion (as written, for read-back)
  bool tracking_enabled = false;  // the CV7 would estimate frame errors; stored and read back only
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // sensor -> vehicle
};

// `Time` timebases of aiding measurements (digest §5.1, [EXT-SDK]).
enum class AidingTimebase : std::uint8_t { kInternalReference = 1, kExternalTime = 2, kTimeOfArrival = 3 };
// Echo control modes (0x13,0x1F, L7791).
enum class AidingEchoMode : std::uint8_t { kSuppressAck = 0, kStandard = 1, kResponse = 2 };

struct AidingResult {
  std::vector<std::uint8_t> reply;          // reply packet(s); empty when ACKs are suppressed
  std::vector<Measurement> measurements;    // accepted aiding, vehicle frame
  std::vector<std::pair<std::uint8_t, ReplyCode>> codes;  // per command: descriptor, reply code
};

class AidingCommandHandler {
 public:
  // `clock` (optional) maps timebase 1 (device reference ns, same as 0xFF,0xD5) to GPS time; without
  // a valid mapping such measurements keep the raw time flagged kDeviceMonotonic. Timebase 2
  // (external, PPS-disciplined) is taken as GPS ns, which is what the CV7 holds once GPS time is
  // set with (0x01,0x72) (digest §9).
  explicit AidingCommandHandler(const time::ClockModel* clock = nullptr) : clock_(clock) {}

  // Handles one whole packet (sync to checksum). `arrival_gps_ns` stamps timebase-3 measurements.
  // Clears and fills `out`.
  void handle_packet(std::span<const std::uint8_t> packet, AidingResult& out, std::int64_t arrival_gps_ns = 0);
  // Handles the fields of an already validated 0x13 payload (reply built the same way).
  void handle_payload(std::span<const std::uint8_t> payload, AidingResult& out, std::int64_t arrival_gps_ns = 0);

  const AidingFrame& frame(std::uint8_t id) const { return frames_[id < kFrames ? id : 0]; }
  AidingEchoMode echo_mode() const { return echo_; }
  // Frames 1..4 (limit 4, L7755); index 0 is the device's own frame (identity).
  static constexpr std::size_t kFrames = 5;

 private:
  ReplyCode frame_config(std::span<const std::uint8_t> data, std::vector<std::uint8_t>& response);
  ReplyCode echo_control(std::span<const std::uint8_t> data, std::vector<std::uint8_t>& response);
  ReplyCode measurement(std::uint8_t desc, std::span<const std::uint8_t> data, std::int64_t arrival_gps_ns,
                        std::vector<Measurement>& out);

  const time::ClockModel* clock_;
  std::array<AidingFrame, kFrames> frames_{};
  AidingEchoMode echo_ = AidingEchoMode::kStandard;
};

}  // namespace navfuse::frontends::mip

// Maps decoded binary messages to core measurements (digest §5.9, §11):
//  - ImuSample from DeltaTheta/DeltaVel (Imu or Common.Deltas) as increments, else from
//    UncompAccel/UncompGyro (Imu or Common.Imu), else from the compensated Accel/AngularRate;
//  - GnssPosition / GnssVelocity per receiver (GNSS1 -> receiver 0, GNSS2 -> 1, GNSS3 -> 2), once
//    per GNSS epoch (the groups repeat 5 Hz data at the message rate, L1133);
//  - the device's INS/attitude solution as a NavSolution (kind device_solution).
#pragma once

#include <array>
#include <optional>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/vectornav/binary_message.hpp"
#include "frontends/vectornav/decoder_options.hpp"
#include "frontends/vectornav/stream_clock.hpp"

namespace navfuse::frontends::vectornav {

class BinaryMapper {
 public:
  BinaryMapper(StreamClock& clock, const DecoderOptions& options) : clock_(clock), options_(options) {}
  // Emits the measurements `m` carries. Returns the number of fields that could not be used
  // (undefined enum value, non-positive DeltaTime...): the caller counts them as decode errors.
  int map(const BinaryMessage& m, DecodeSink& sink);

 private:
  Stamp message_stamp(const BinaryMessage& m);
  int map_imu(const BinaryMessage& m, const Stamp& stamp, DecodeSink& sink);
  int map_gnss(const BinaryMessage& m, std::size_t receiver, const Stamp& stamp, DecodeSink& sink);
  int map_solution(const BinaryMessage& m, const Stamp& stamp, DecodeSink& sink);

  StreamClock& clock_;
  DecoderOptions options_;
  // Last GNSS epoch (GpsTow, ns) emitted per receiver, for position and velocity separately.
  std::array<std::optional<std::uint64_t>, kGnssReceivers> last_position_tow_{};
  std::array<std::optional<std::uint64_t>, kGnssReceivers> last_velocity_tow_{};
  std::optional<std::int64_t> last_rate_time_ns_;
};

// GnssFix (Table 2.41) to core; nullopt for the undefined values 5 and 6.
std::optional<GnssFixType> fix_from_vn(std::uint8_t fix);
// Core fix to the closest VN value (VN has one differential class, SBAS, and no PPP/DR value).
std::uint8_t vn_from_fix(GnssFixType fix);

}  // namespace navfuse::frontends::vectornav

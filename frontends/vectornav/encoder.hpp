// Writes core measurements the way a VN-300 configured for fusion emits them
// (fusion_setup_commands() in commands.hpp), one message per measurement:
//  - ImuSample   -> binary Time{TimeStartup, TimeGps, TimeStatus} + Imu{ImuStatus, UncompAccel,
//                   UncompGyro, SensSat} for rates, or Imu{ImuStatus, DeltaTheta, DeltaVel,
//                   SensSat} for increments;
//  - NavSolution -> binary Time{...} + Attitude{Ypr, Quaternion, YprU} + Ins{InsStatus, PosLla,
//                   VelBody, VelNed, PosU, VelU} (the device solution);
//  - GnssPosition / GnssVelocity -> binary GNSS1/GNSS2/GNSS3 (receiver_id 0/1/2) with GpsTow,
//                   GpsWeek, GnssTimeInfo, GnssFix and the position (NumSats, PosLla,
//                   PosUncertainty) or velocity (VelNed, VelUncertainty) types;
//  - GnssHeading -> ASCII "$VNRRG,98,<percent>,<heading>" (Reg 98 is the only GNSS-compass
//                   heading output of this ICD, digest §5.9);
//  - VehicleSpeed -> ASCII "$VNWRG,50,<speed>,0,0", the device's echo of a velocity-aiding write
//                   (Reg 50 takes the speed along body x, L3732).
// Everything else (wheel speeds/ticks, external aiding, magnetometer, pressure) returns false.
//
// The protocol's resolution: binary floats are IEEE binary32 (so ~1e-7 relative), positions
// binary64; scalar PosU/VelU carry the largest axis sigma; ASCII heading 1e-3 deg, speed 1e-4 m/s.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/vectornav/ascii_sentence.hpp"
#include "frontends/vectornav/binary_message.hpp"

namespace navfuse::frontends::vectornav {

struct EncoderOptions {
  // TimeStartup of the first measurement (the device has been running this long, ns).
  std::int64_t startup_at_first_ns = 5'000'000'000;
  // Checksum of the ASCII sentences (Reg 30 AsciiChecksum).
  AsciiChecksum ascii_checksum = AsciiChecksum::kXor8;
};

class VnMeasurementEncoder final : public MeasurementEncoder {
 public:
  explicit VnMeasurementEncoder(const EncoderOptions& options = {}) : options_(options) {}
  bool encode(const Measurement& m, std::vector<std::uint8_t>& out) override;

 private:
  bool encode_imu(const ImuSample& s, std::vector<std::uint8_t>& out);
  bool encode_solution(const NavSolution& s, std::vector<std::uint8_t>& out);
  bool encode_gnss_position(const GnssPosition& p, std::vector<std::uint8_t>& out);
  bool encode_gnss_velocity(const GnssVelocity& v, std::vector<std::uint8_t>& out);
  bool encode_heading(const GnssHeading& h, std::vector<std::uint8_t>& out);
  bool encode_speed(const VehicleSpeed& s, std::vector<std::uint8_t>& out);
  // Starts a message with the Time group for `header`; false if the time cannot be carried.
  bool begin_timed(const MeasurementHeader& header);
  bool set_gnss_time(std::size_t receiver, const MeasurementHeader& header);
  bool finish(std::vector<std::uint8_t>& out);

  EncoderOptions options_;
  BinaryMessage msg_;
  std::optional<std::int64_t> first_time_ns_;
  std::uint8_t split_id_ = 0;
};

}  // namespace navfuse::frontends::vectornav

// One line of KF-GINS-style IMU text -> core ImuSample.
//
// The line layout is the one KF-GINS reads (i2Nav-Robot/KF-GINS, README "IMU data"): GPS seconds
// of week at the end of the sample interval, then angle increments x y z (rad) and velocity
// increments x y z (m/s) in the IMU's own sensor axes. Further columns (temperature, a sample
// counter...) are tolerated and ignored. The increments become an ImuSample of quantity
// kIncrements in frame kSensor: the engine rotates them into the vehicle frame by
// imu.mounting_rpy_deg like every IMU's.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"
#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends::imutxt {

inline constexpr std::size_t kColumns = 7;  // tow, 3 angle increments, 3 velocity increments

struct ImuLine {
  double tow_s = 0.0;
  Eigen::Vector3d dtheta_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d dvel_mps = Eigen::Vector3d::Zero();
};

enum class LineKind : std::uint8_t {
  kData,     // a sample
  kComment,  // a comment or column header: starts with '#', '%', '/' or has no number at all
  kBlank,
  kDamaged,  // meant as data but unusable: fewer than 7 columns, a non-number, NaN/inf, TOW
             // outside [0, 604800)
};

struct ParsedLine {
  LineKind kind = LineKind::kDamaged;
  ImuLine imu;  // valid with kData
};

ParsedLine parse_line(std::string_view line);

// The sample for a line at `time_ns` (GPS when the week is known), `dt_s` since the previous
// sample (0 for the first: the engine then takes the interval from the sample times).
ImuSample to_core(const ImuLine& line, std::int64_t time_ns, TimeSource source, double dt_s);

// The generic record `navfuse decode` prints for a sample.
FrameRecord to_record(const ImuLine& line, std::uint64_t offset);

}  // namespace navfuse::frontends::imutxt

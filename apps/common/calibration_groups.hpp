// The estimated calibration states as the outputs print them: one group per quantity (gyro and
// accel biases, odometer scale error, residual mounting, GNSS lever arm, scale factors, GNSS time
// offset), each
// with its unit, axes, value and 1-sigma std, converted from the solution's SI once here. The CSV
// columns (apps/output/csv_pose_writer.cpp) and the run summary's `calibration` section are both
// printed from these groups.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

struct CalibrationGroup {
  std::string_view name;  // "gyro_bias"
  std::string_view unit;  // "deg_h"; "" for a dimensionless fraction
  std::array<std::string_view, 3> axes;  // "x", "y", "z"; one "" for a scalar
  int count = 3;
  int decimals = 6;       // CSV digits after the point
  bool estimated = false;  // false: not estimated (or not yet valid): printed as nan / left out
  std::array<double, 3> value{};
  std::array<double, 3> std{};

  // "<name>[_std]_<axis>_<unit>", empty parts left out: gyro_bias_std_x_deg_h,
  // odometer_scale_error_std.
  std::string column(int axis, bool is_std) const;
};

inline constexpr std::size_t kCalibrationGroups = 8;
// Biases in the sensor frame (as NavSolution reports them), the rest in the vehicle frame.
std::array<CalibrationGroup, kCalibrationGroups> calibration_groups(const NavSolution& s);

}  // namespace navfuse::apps

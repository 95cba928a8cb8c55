#include "apps/common/calibration_groups.hpp"

#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

constexpr std::array<std::string_view, 3> kXyz{"x", "y", "z"};
constexpr double kRadPerSecondToDegPerHour = rot::kRadToDeg * 3600.0;
constexpr double kPpm = 1e6;

template <int N>
CalibrationGroup group(std::string_view name, std::string_view unit, std::array<std::string_view, 3> axes,
                       int decimals, bool estimated, const Eigen::Matrix<double, N, 1>& value,
                       const Eigen::Matrix<double, N, 1>& std, double scale) {
  CalibrationGroup g{.name = name, .unit = unit, .axes = axes, .count = N, .decimals = decimals,
                     .estimated = estimated, .value = {}, .std = {}};
  for (int i = 0; i < N; ++i) {
    g.value[static_cast<std::size_t>(i)] = value[i] * scale;
    g.std[static_cast<std::size_t>(i)] = std[i] * scale;
  }
  return g;
}

}  // namespace

std::string CalibrationGroup::column(int axis, bool is_std) const {
  std::string out(name);
  const auto part = [&out](std::string_view p) {
    if (p.empty()) return;
    out += '_';
    out += p;
  };
  if (is_std) part("std");
  part(axes[static_cast<std::size_t>(axis)]);
  part(unit);
  return out;
}

std::array<CalibrationGroup, kCalibrationGroups> calibration_groups(const NavSolution& s) {
  // Biases and the other states are estimated from levelling on; before it they mean nothing.
  const bool valid = (s.header.valid & NavSolution::kValidBiases) != 0;
  const auto& c = s.calibration;
  using V1 = Eigen::Matrix<double, 1, 1>;
  return {
      group<3>("gyro_bias", "deg_h", kXyz, 4, valid, s.gyro_bias_rps, s.gyro_bias_std_rps, kRadPerSecondToDegPerHour),
      group<3>("accel_bias", "mps2", kXyz, 6, valid, s.accel_bias_mps2, s.accel_bias_std_mps2, 1.0),
      group<1>("odometer_scale_error", "", {""}, 6, valid && c.odometer_scale_error.estimated,
               V1(c.odometer_scale_error.value), V1(c.odometer_scale_error.std), 1.0),
      group<2>("mount", "deg", {"pitch", "yaw"}, 5, valid && c.mount_pitch_yaw_rad.estimated,
               c.mount_pitch_yaw_rad.value, c.mount_pitch_yaw_rad.std, rot::kRadToDeg),
      group<3>("gnss_lever_arm", "m", kXyz, 4, valid && c.gnss_lever_arm_m.estimated, c.gnss_lever_arm_m.value,
               c.gnss_lever_arm_m.std, 1.0),
      group<3>("gyro_scale", "ppm", kXyz, 1, valid && c.gyro_scale.estimated, c.gyro_scale.value,
               c.gyro_scale.std, kPpm),
      group<3>("accel_scale", "ppm", kXyz, 1, valid && c.accel_scale.estimated, c.accel_scale.value,
               c.accel_scale.std, kPpm),
      group<1>("gnss_time_offset", "ms", {""}, 2, valid && c.gnss_time_offset_s.estimated,
               V1(c.gnss_time_offset_s.value), V1(c.gnss_time_offset_s.std), 1e3),
  };
}

}  // namespace navfuse::apps

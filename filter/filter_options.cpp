#include "filter/filter_options.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {
namespace {

Eigen::Vector3d vec(const navfuse::config::Vec3& v) { return {v[0], v[1], v[2]}; }

constexpr double kDegPerHourToRadPerSecond = rot::kDegToRad / 3600.0;
// Random-walk coefficients: X per sqrt(hour) = X / 60 per sqrt(second).
constexpr double kPerRootHourToPerRootSecond = 1.0 / 60.0;

}  // namespace

FilterOptions options_from_config(const navfuse::config::Config& config) {
  FilterOptions o;
  const auto& imu = config.imu;
  o.imu.gyro_arw_rad_rts = imu.gyro_arw_deg_rthr * rot::kDegToRad * kPerRootHourToPerRootSecond;
  o.imu.gyro_bias_std_rps = imu.gyro_bias_instability_deg_hr * kDegPerHourToRadPerSecond;
  o.imu.gyro_bias_corr_time_s = imu.gyro_bias_corr_time_s;
  o.imu.accel_vrw_mps_rts = imu.accel_vrw_mps_rthr * kPerRootHourToPerRootSecond;
  o.imu.accel_bias_std_mps2 = imu.accel_bias_instability_mps2;
  o.imu.accel_bias_corr_time_s = imu.accel_bias_corr_time_s;
  o.imu.initial_gyro_bias_std_rps = imu.initial_gyro_bias_std_deg_hr * kDegPerHourToRadPerSecond;
  o.imu.initial_accel_bias_std_mps2 = imu.initial_accel_bias_std_mps2;
  o.mounting_rpy_rad = vec(imu.mounting_rpy_deg) * rot::kDegToRad;
  o.gnss_lever_arm_m = vec(config.gnss.lever_arm_m);
  o.gnss_secondary_lever_arm_m = vec(config.gnss.secondary_lever_arm_m);
  o.wheel_lever_arm_m = vec(config.wheel.lever_arm_m);
  o.wheel_speed_std_mps = config.wheel.speed_std_mps;
  o.wheel_m_per_tick = config.wheel.m_per_tick;
  // The odometer scale error is a state unless its prior is 0 (the scale is trusted as given).
  o.initial_wheel_scale_std = config.wheel.initial_scale_std;
  o.states.wheel_scale = config.wheel.initial_scale_std > 0.0;

  // Which constraints hold (Groves 2nd ed. §13.1.3 land-vehicle NHC; §16.2.4 ZUPT for
  // pedestrians). Only a wheeled vehicle cannot slip sideways; a boat or an aircraft is never
  // truly at rest, so only land and pedestrian platforms may assume zero velocity at stops.
  using navfuse::config::Platform;
  o.land_vehicle = config.platform == Platform::kLand;
  o.zero_velocity_updates =
      config.platform == Platform::kLand || config.platform == Platform::kPedestrian;
  // A walker rarely exceeds 1.5 m/s; at 0.5 m/s an RTK velocity (~0.02 m/s) still gives the
  // course to ~2 deg, and kinematic_max_course_std_rad refuses a noisier one.
  constexpr double kPedestrianAlignmentSpeed_mps = 0.5;
  o.kinematic_alignment_speed_mps = config.alignment.min_speed_mps.value_or(
      config.platform == Platform::kPedestrian ? kPedestrianAlignmentSpeed_mps
                                               : o.kinematic_alignment_speed_mps);
  if (config.alignment.initial_heading_deg) {
    o.initial_heading_rad = rot::wrap_pi(*config.alignment.initial_heading_deg * rot::kDegToRad);
  }
  return o;
}

}  // namespace navfuse::filter

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
  // ppm to fraction by division: 1000 / 1e6 is the double nearest 1e-3, as the literal default is.
  constexpr double kPpm = 1e6;
  o.imu.initial_gyro_scale_std = imu.initial_gyro_scale_std_ppm / kPpm;
  o.imu.initial_accel_scale_std = imu.initial_accel_scale_std_ppm / kPpm;
  o.states.gyro_scale = imu.estimate_gyro_scale;
  o.states.accel_scale = imu.estimate_accel_scale;
  o.states.mounting = imu.estimate_mounting;
  o.initial_mount_std_rad = imu.initial_mounting_std_deg * rot::kDegToRad;
  o.states.gnss_lever_arm = config.gnss.estimate_lever_arm;
  o.initial_lever_arm_std_m = config.gnss.initial_lever_arm_std_m;
  o.states.gnss_time_offset = config.gnss.estimate_time_offset;
  o.initial_gnss_time_offset_std_s = config.gnss.initial_time_offset_std_s;
  o.max_imu_gap_s = imu.max_gap_s;
  o.mounting_rpy_rad = vec(imu.mounting_rpy_deg) * rot::kDegToRad;
  o.gnss_lever_arm_m = vec(config.gnss.lever_arm_m);
  o.gnss_secondary_lever_arm_m = vec(config.gnss.secondary_lever_arm_m);
  o.wheel_lever_arm_m = vec(config.wheel.lever_arm_m);
  o.wheel_speed_std_mps = config.wheel.speed_std_mps;
  o.wheel_m_per_tick = config.wheel.m_per_tick;
  // The odometer scale error is a state unless its prior is 0 (the scale is trusted as given).
  o.initial_wheel_scale_std = config.wheel.initial_scale_std;
  o.states.wheel_scale = config.wheel.initial_scale_std > 0.0;
  const auto& g = config.gnss;
  auto scale = [&o](GnssFixType fix, double v) { o.gnss_position_std_scale[static_cast<std::size_t>(fix)] = v; };
  scale(GnssFixType::kRtkFixed, g.std_scale_rtk_fixed);
  scale(GnssFixType::kRtkFloat, g.std_scale_rtk_float);
  scale(GnssFixType::kPpp, g.std_scale_ppp);
  scale(GnssFixType::kDgnss, g.std_scale_dgnss);
  scale(GnssFixType::kSbas, g.std_scale_dgnss);
  scale(GnssFixType::kFix2D, g.std_scale_single);
  scale(GnssFixType::kFix3D, g.std_scale_single);
  o.gnss_velocity_std_scale = g.velocity_std_scale;
  o.gnss_timeout_s = g.timeout_s;
  o.gnss_recovery_s = g.recovery_s;
  o.gnss_jump_hold_s = g.jump_hold_s;
  o.gnss_jump_min_m = g.jump_min_m;
  o.gnss_jump_gate = config.gates.gnss_jump;
  o.output_jump_blend_s = config.output.jump_blend_s;
  o.output_jump_blend_min_m = config.output.jump_blend_min_m;
  const auto& gates = config.gates;
  o.chi2_gate = {gates.chi2_1d, gates.chi2_2d, gates.chi2_3d};
  auto own_gate = [&o](GatedAid aid, const std::optional<double>& chi2) {
    o.aid_chi2_gate[static_cast<std::size_t>(aid)] = chi2.value_or(0.0);
  };
  own_gate(GatedAid::kGnssPosition, gates.gnss_position);
  own_gate(GatedAid::kGnssVelocity, gates.gnss_velocity);
  own_gate(GatedAid::kGnssHeading, gates.gnss_heading);
  own_gate(GatedAid::kOdometry, gates.odometry);
  own_gate(GatedAid::kNhc, gates.nhc);
  own_gate(GatedAid::kStationary, gates.stationary);
  own_gate(GatedAid::kGravity, gates.gravity);
  own_gate(GatedAid::kPressure, gates.pressure);
  own_gate(GatedAid::kMagnetometer, gates.magnetometer);
  own_gate(GatedAid::kExternalPosition, gates.external_position);
  own_gate(GatedAid::kExternalVelocity, gates.external_velocity);
  own_gate(GatedAid::kExternalHeading, gates.external_heading);
  o.max_latency_s = config.timing.max_latency_s;
  const auto& nhc = config.nhc;
  if (nhc.lever_arm_m) o.nhc_lever_arm_m = vec(*nhc.lever_arm_m);
  if (nhc.lever_arm_std_m) {
    o.nhc_lever_arm_std_m = vec(*nhc.lever_arm_std_m);
  } else if (!nhc.lever_arm_m && vec(config.wheel.lever_arm_m).isZero(0.0)) {
    o.nhc_lever_arm_std_m = kUnknownNonSlipPointStdM;
  }
  o.nhc_lateral_std_mps = nhc.lateral_std_mps;
  o.nhc_vertical_std_mps = nhc.vertical_std_mps;
  o.nhc_min_speed_mps = nhc.min_speed_mps;
  o.nhc_interval_s = nhc.interval_s;
  const auto& zupt = config.zupt;
  o.zupt_std_mps = zupt.std_mps;
  o.stationary_window_s = zupt.window_s;
  o.stationary_gyro_rps = zupt.max_rate_rad_s;
  o.stationary_accel_std_mps2 = zupt.max_accel_std_mps2;
  o.stationary_max_speed_mps = zupt.max_speed_mps;
  o.level_time_s = config.alignment.level_time_s;
  o.level_timeout_s = config.alignment.level_timeout_s;
  o.initial_heading_std_rad = config.alignment.initial_heading_std_deg * rot::kDegToRad;
  if (config.alignment.initial_tilt_std_deg) {
    o.initial_tilt_std_rad = *config.alignment.initial_tilt_std_deg * rot::kDegToRad;
  }
  o.initial_velocity_std_mps = config.alignment.initial_velocity_std_mps;
  o.imu_time_offset_s = imu.time_offset_s;
  o.adaptation.window_s = config.adaptation.window_s;
  o.adaptation.inflate_ratio = config.adaptation.inflate_ratio;
  o.adaptation.max_process_noise_scale = config.adaptation.max_process_noise_scale;
  o.adaptation.max_measurement_noise_scale = config.adaptation.max_measurement_noise_scale;
  o.gnss_time_offset_s = config.gnss.time_offset_s;
  o.wheel_time_offset_s = config.wheel.time_offset_s;

  // Which constraints hold (Groves 2nd ed. §13.1.3 land-vehicle NHC; §16.2.4 ZUPT for
  // pedestrians). Only a wheeled vehicle cannot slip sideways; a boat or an aircraft is never
  // truly at rest, so only land and pedestrian platforms may assume zero velocity at stops.
  using navfuse::config::Platform;
  // An explicit nhc.enabled / alignment.course / zupt.enabled overrides the platform's choice.
  const bool land = config.platform == Platform::kLand;
  o.land_vehicle = nhc.enabled.value_or(land);
  o.course_alignment = config.alignment.course.value_or(land);
  // A generic platform (the default) assumes nothing about how it moves: no NHC, no heading
  // from the course, but zero-velocity updates when the IMU is quiet (a vibrating boat or
  // aircraft is never detected as stationary anyway).
  o.zero_velocity_updates = zupt.enabled.value_or(config.platform == Platform::kGeneric || land ||
                                                  config.platform == Platform::kPedestrian);
  // Gravity as the tilt reference without velocity aiding: the accelerations of a walker or a
  // vessel average out within seconds (steps, waves); a car's (braking, a long bend) and an
  // aircraft's (a coordinated turn) do not, and their INS holds its tilt better alone (simulated
  // reference drive without aiding: roll RMS 0.04 deg alone, 0.12 deg with gravity;
  // tests/filter/accel_tilt_scenario_test.cpp).
  o.accel_tilt.enabled = config.accel_tilt.enabled.value_or(config.platform == Platform::kPedestrian ||
                                                            config.platform == Platform::kMarine);
  // A walker rarely exceeds 1.5 m/s; at 0.5 m/s an RTK velocity (~0.02 m/s) still gives the
  // course to ~2 deg, and kinematic_max_course_std_rad refuses a noisier one.
  constexpr double kPedestrianAlignmentSpeed_mps = 0.5;
  o.kinematic_alignment_speed_mps = config.alignment.min_speed_mps.value_or(
      config.platform == Platform::kPedestrian ? kPedestrianAlignmentSpeed_mps
                                               : o.kinematic_alignment_speed_mps);
  if (config.magnetometer.heading_std_deg) {
    o.magnetometer.enabled = true;
    o.magnetometer.heading_std_rad = *config.magnetometer.heading_std_deg * rot::kDegToRad;
  }
  if (config.magnetometer.declination_deg) {
    o.magnetometer.declination_rad = *config.magnetometer.declination_deg * rot::kDegToRad;
  }
  o.magnetometer.hard_iron_gauss = vec(config.magnetometer.hard_iron_gauss);
  o.accel_tilt.std_mps2 = config.accel_tilt.std_mps2;
  o.accel_tilt.max_deviation_mps2 = config.accel_tilt.max_deviation_mps2;
  if (config.baro.height_std_m) {
    o.baro.enabled = true;
    o.baro.height_std_m = *config.baro.height_std_m;
  }
  if (config.alignment.initial_heading_deg) {
    o.initial_heading_rad = rot::wrap_pi(*config.alignment.initial_heading_deg * rot::kDegToRad);
  }
  return o;
}

double FilterOptions::time_offset_s(MeasurementKind kind) const {
  switch (kind) {
    case MeasurementKind::kImu: return imu_time_offset_s;
    case MeasurementKind::kGnssPosition:
    case MeasurementKind::kGnssVelocity:
    case MeasurementKind::kGnssHeading: return gnss_time_offset_s;
    case MeasurementKind::kWheelSpeed:
    case MeasurementKind::kVehicleSpeed:
    case MeasurementKind::kWheelTicks: return wheel_time_offset_s;
    default: return 0.0;
  }
}

bool FilterOptions::fuses(MeasurementKind kind) const {
  if ((aiding_off_mask & (1u << static_cast<unsigned>(kind))) != 0) return false;
  switch (kind) {
    case MeasurementKind::kMagnetometer: return magnetometer.enabled;
    case MeasurementKind::kPressure: return baro.enabled;
    default: return true;
  }
}

}  // namespace navfuse::filter

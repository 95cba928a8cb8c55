// options_from_config for the filter keys: the config's defaults are FilterOptions' own defaults
// (so a config that leaves a key out changes nothing), each key reaches its option in SI units,
// and the explicit switches override what the platform would choose.
#include <gtest/gtest.h>

#include "core/config/config.hpp"
#include "filter/filter_options.hpp"

namespace navfuse::filter {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(ConfigOptions, ConfigDefaultsAreTheFilterDefaults) {
  config::Config c = config::defaults_for(config::DeviceProfile::kGeneric);
  c.platform = config::Platform::kLand;  // FilterOptions{} assumes a land vehicle
  const FilterOptions o = options_from_config(c);
  const FilterOptions d;
  EXPECT_EQ(o.imu.initial_gyro_scale_std, d.imu.initial_gyro_scale_std);
  EXPECT_EQ(o.imu.initial_accel_scale_std, d.imu.initial_accel_scale_std);
  EXPECT_EQ(o.states.gyro_scale, d.states.gyro_scale);
  EXPECT_EQ(o.states.accel_scale, d.states.accel_scale);
  EXPECT_EQ(o.states.mounting, d.states.mounting);
  EXPECT_EQ(o.states.gnss_lever_arm, d.states.gnss_lever_arm);
  EXPECT_EQ(o.states.wheel_scale, d.states.wheel_scale);
  EXPECT_EQ(o.initial_mount_std_rad, d.initial_mount_std_rad);
  EXPECT_EQ(o.initial_lever_arm_std_m, d.initial_lever_arm_std_m);
  EXPECT_EQ(o.max_imu_gap_s, d.max_imu_gap_s);
  EXPECT_EQ(o.gnss_timeout_s, d.gnss_timeout_s);
  EXPECT_EQ(o.gnss_recovery_s, d.gnss_recovery_s);
  EXPECT_EQ(o.chi2_gate, d.chi2_gate);
  EXPECT_EQ(o.max_latency_s, d.max_latency_s);
  EXPECT_EQ(o.nhc_lateral_std_mps, d.nhc_lateral_std_mps);
  EXPECT_EQ(o.nhc_vertical_std_mps, d.nhc_vertical_std_mps);
  EXPECT_EQ(o.nhc_min_speed_mps, d.nhc_min_speed_mps);
  EXPECT_EQ(o.nhc_interval_s, d.nhc_interval_s);
  EXPECT_EQ(o.zupt_std_mps, d.zupt_std_mps);
  EXPECT_EQ(o.stationary_window_s, d.stationary_window_s);
  EXPECT_EQ(o.stationary_gyro_rps, d.stationary_gyro_rps);
  EXPECT_EQ(o.stationary_accel_std_mps2, d.stationary_accel_std_mps2);
  EXPECT_EQ(o.stationary_max_speed_mps, d.stationary_max_speed_mps);
  EXPECT_EQ(o.level_time_s, d.level_time_s);
  EXPECT_EQ(o.level_timeout_s, d.level_timeout_s);
  EXPECT_EQ(o.initial_heading_std_rad, d.initial_heading_std_rad);
  EXPECT_EQ(o.initial_tilt_std_rad, d.initial_tilt_std_rad);
  EXPECT_EQ(o.initial_velocity_std_mps, d.initial_velocity_std_mps);
  EXPECT_EQ(o.land_vehicle, d.land_vehicle);
  EXPECT_EQ(o.course_alignment, d.course_alignment);
  EXPECT_EQ(o.zero_velocity_updates, d.zero_velocity_updates);
}

TEST(ConfigOptions, KeysReachTheirOptionsInSiUnits) {
  const config::Config c = config::load_from_string(
      "imu: {estimate_gyro_scale: true, initial_gyro_scale_std_ppm: 300, estimate_accel_scale: true,"
      " initial_accel_scale_std_ppm: 2500, estimate_mounting: true, initial_mounting_std_deg: 2,"
      " max_gap_s: 0.25}\n"
      "gnss: {estimate_lever_arm: true, initial_lever_arm_std_m: 0.5, timeout_s: 4, recovery_s: 6}\n"
      "alignment: {initial_heading_deg: 30, initial_heading_std_deg: 90, level_time_s: 3,"
      " level_timeout_s: 20, initial_tilt_std_deg: 1.5, initial_velocity_std_mps: 0.3}\n"
      "nhc: {lateral_std_mps: 0.2, vertical_std_mps: 0.4, min_speed_mps: 2.5, interval_s: 0.2}\n"
      "zupt: {std_mps: 0.005, window_s: 0.4, max_rate_rad_s: 0.03, max_accel_std_mps2: 0.1,"
      " max_speed_mps: 0.2}\n"
      "gates: {chi2_1d: 6.63, chi2_2d: 9.21, chi2_3d: 11.34}\ntiming: {max_latency_s: 0.5}\n");
  const FilterOptions o = options_from_config(c);
  EXPECT_DOUBLE_EQ(o.imu.initial_gyro_scale_std, 3e-4);
  EXPECT_DOUBLE_EQ(o.imu.initial_accel_scale_std, 2.5e-3);
  EXPECT_TRUE(o.states.gyro_scale);
  EXPECT_TRUE(o.states.accel_scale);
  EXPECT_TRUE(o.states.mounting);
  EXPECT_TRUE(o.states.gnss_lever_arm);
  EXPECT_EQ(o.states.active_dimension(), 27);  // every optional state on
  EXPECT_DOUBLE_EQ(o.initial_mount_std_rad, 2.0 * kPi / 180.0);
  EXPECT_EQ(o.initial_lever_arm_std_m, 0.5);
  EXPECT_EQ(o.max_imu_gap_s, 0.25);
  EXPECT_EQ(o.gnss_timeout_s, 4);
  EXPECT_EQ(o.gnss_recovery_s, 6);
  EXPECT_DOUBLE_EQ(o.initial_heading_std_rad, kPi / 2.0);
  EXPECT_EQ(o.level_time_s, 3);
  EXPECT_EQ(o.level_timeout_s, 20);
  EXPECT_DOUBLE_EQ(o.initial_tilt_std_rad.value_or(0.0), 1.5 * kPi / 180.0);
  EXPECT_EQ(o.initial_velocity_std_mps.value_or(0.0), 0.3);
  EXPECT_EQ(o.nhc_lateral_std_mps, 0.2);
  EXPECT_EQ(o.nhc_vertical_std_mps, 0.4);
  EXPECT_EQ(o.nhc_min_speed_mps, 2.5);
  EXPECT_EQ(o.nhc_interval_s, 0.2);
  EXPECT_EQ(o.zupt_std_mps, 0.005);
  EXPECT_EQ(o.stationary_window_s, 0.4);
  EXPECT_EQ(o.stationary_gyro_rps, 0.03);
  EXPECT_EQ(o.stationary_accel_std_mps2, 0.1);
  EXPECT_EQ(o.stationary_max_speed_mps, 0.2);
  EXPECT_EQ(o.chi2_gate, (std::array<double, 3>{6.63, 9.21, 11.34}));
  EXPECT_EQ(o.max_latency_s, 0.5);
}

TEST(ConfigOptions, AnAidsGateReplacesTheDimensionGateForThatAidOnly) {
  const FilterOptions o = options_from_config(config::load_from_string(
      "gates: {chi2_1d: 6.63, chi2_3d: 11.34, gnss_position: 30, odometry: 3.84, stationary: 50}\n"));
  EXPECT_EQ(o.gate_for(GatedAid::kGnssPosition, 3), 30.0);
  EXPECT_EQ(o.gate_for(GatedAid::kGnssPosition, 2), 30.0);  // whatever the update's rows
  EXPECT_EQ(o.gate_for(GatedAid::kOdometry, 1), 3.84);
  EXPECT_EQ(o.gate_for(GatedAid::kStationary, 3), 50.0);
  // Unset: by the update's dimension.
  EXPECT_EQ(o.gate_for(GatedAid::kGnssVelocity, 3), 11.34);
  EXPECT_EQ(o.gate_for(GatedAid::kGnssHeading, 1), 6.63);
  EXPECT_EQ(o.gate_for(GatedAid::kNhc, 2), 18.42);
  EXPECT_EQ(o.gate_for(GatedAid::kExternalPosition, 1), 6.63);
  // The defaults set no gate of any aid's own.
  const FilterOptions d = options_from_config(config::defaults_for(config::DeviceProfile::kGeneric));
  for (double g : d.aid_chi2_gate) EXPECT_EQ(g, 0.0);
}

TEST(ConfigOptions, NhcPointIsItsOwnKeyOrTheWheel) {
  // Unset: the constraint is applied at the wheel (odometer) point.
  const FilterOptions wheel = options_from_config(config::load_from_string("wheel: {lever_arm_m: [-1.2, 0, 0.3]}\n"));
  EXPECT_FALSE(wheel.nhc_lever_arm_m);
  EXPECT_EQ(wheel.wheel_lever_arm_m, Eigen::Vector3d(-1.2, 0.0, 0.3));
  // A car with no odometer: the rear-axle centre given for the constraint alone.
  const config::Config c = config::load_from_string("nhc: {lever_arm_m: [-1.5, 0.1, 0.8]}\n");
  ASSERT_TRUE(c.nhc.lever_arm_m);
  const FilterOptions o = options_from_config(c);
  ASSERT_TRUE(o.nhc_lever_arm_m);
  EXPECT_EQ(*o.nhc_lever_arm_m, Eigen::Vector3d(-1.5, 0.1, 0.8));
  // `~` clears it; the dump prints it and reads back.
  const config::Config round = config::load_from_string(config::to_yaml(c));
  ASSERT_TRUE(round.nhc.lever_arm_m);
  EXPECT_EQ(*round.nhc.lever_arm_m, *c.nhc.lever_arm_m);
  EXPECT_FALSE(config::load_from_string(config::to_yaml(config::load_from_string("nhc: {lever_arm_m: ~}\n")))
                   .nhc.lever_arm_m);
}

TEST(ConfigOptions, AnUnknownNhcPointIsAGuessWithItsUncertainty) {
  // Nothing says where the car does not slip: at the IMU, known only to kUnknownNonSlipPointStdM.
  EXPECT_EQ(options_from_config(config::load_from_string("platform: land\n")).nhc_lever_arm_std_m,
            Eigen::Vector3d(1.5, 0.5, 0.5));
  // The odometer's point or the constraint's own key says where: known.
  EXPECT_EQ(options_from_config(config::load_from_string("wheel: {lever_arm_m: [-1.2, 0, 0.3]}\n")).nhc_lever_arm_std_m,
            Eigen::Vector3d::Zero());
  EXPECT_EQ(options_from_config(config::load_from_string("nhc: {lever_arm_m: [0, 0, 0]}\n")).nhc_lever_arm_std_m,
            Eigen::Vector3d::Zero());
  // Given: as given, and it survives the dump.
  const config::Config c = config::load_from_string("nhc: {lever_arm_std_m: [0.2, 0.1, 0.3]}\n");
  EXPECT_EQ(options_from_config(c).nhc_lever_arm_std_m, Eigen::Vector3d(0.2, 0.1, 0.3));
  EXPECT_EQ(options_from_config(config::load_from_string(config::to_yaml(c))).nhc_lever_arm_std_m,
            Eigen::Vector3d(0.2, 0.1, 0.3));
  EXPECT_THROW(config::load_from_string("nhc: {lever_arm_std_m: [-1, 0, 0]}\n"), config::ConfigError);
}

TEST(ConfigOptions, ExplicitSwitchesOverrideThePlatform) {
  // A land vehicle without NHC (e.g. a tracked vehicle that skids), course alignment kept.
  auto land = config::load_from_string("platform: land\nnhc: {enabled: false}\n");
  EXPECT_FALSE(options_from_config(land).land_vehicle);
  EXPECT_TRUE(options_from_config(land).course_alignment);
  EXPECT_TRUE(options_from_config(land).zero_velocity_updates);
  // A cart pushed by a walker: NHC on, ZUPT off, course as heading.
  auto pedestrian = config::load_from_string(
      "platform: pedestrian\nnhc: {enabled: true}\nzupt: {enabled: false}\nalignment: {course: true}\n");
  EXPECT_TRUE(options_from_config(pedestrian).land_vehicle);
  EXPECT_FALSE(options_from_config(pedestrian).zero_velocity_updates);
  EXPECT_TRUE(options_from_config(pedestrian).course_alignment);
  // A boat at a mooring: ZUPT forced on.
  auto marine = config::load_from_string("platform: marine\nzupt: {enabled: true}\n");
  EXPECT_TRUE(options_from_config(marine).zero_velocity_updates);
  EXPECT_FALSE(options_from_config(marine).land_vehicle);
}

}  // namespace
}  // namespace navfuse::filter

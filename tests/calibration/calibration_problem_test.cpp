// The calibration on a simulated drive with a known installation (sim calibration_drive: RTK GNSS
// at 10 Hz, industrial IMU with its noise, biases and scale factors, mounted at roll 0.3, pitch
// 1.5, yaw -2.0 deg, its clock 50 ms behind GPS time, 0.5 % odometer scale error, antenna at
// (0.8, -0.4, -1.3) m), starting from a configuration that is wrong in all of them but roll.
// The starting trajectory is the truth on the configured clock (what the smoother gives is
// tested end to end in tests/apps/calibration_scenario_test.cpp).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "calibration/calibration_problem.hpp"
#include "sim_log.hpp"

namespace navfuse::calib {
namespace {

constexpr double kSigmas = 3.0;  // a reported std dev "covers" an error within this many

TEST(CalibrationProblem, RecoversSimulatedInstallation) {
  const sim::Scenario scenario = sim::make_scenario("calibration_drive");
  const testing::StartingSetup start{.lever_arm_m = scenario.gnss.lever_arm_m + Eigen::Vector3d(0.3, -0.2, 0.4),
                                     .mounting_rpy_deg = Eigen::Vector3d(scenario.imu.mounting_rpy_deg.x(), 0.0, 0.0),
                                     .imu_time_offset_s = 0.0};
  const testing::SimLog s = testing::sim_log(scenario, start);
  const CalibrationResult r = calibrate(s.log);
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_TRUE(r.covariance_ok) << r.message;
  ASSERT_TRUE(r.mounting_estimated);
  ASSERT_TRUE(r.odometer_scale.has_value());

  const Eigen::Vector3d lever_err = r.gnss_lever_arm_m.value - scenario.gnss.lever_arm_m;
  const Eigen::Vector3d mount_err_deg = r.mounting_rpy_rad.value * rot::kRadToDeg - scenario.imu.mounting_rpy_deg;
  const double dt_err_s = r.imu_time_offset_s.value - scenario.imu.time_offset_s;
  const double scale_err = r.odometer_scale->value - (1.0 + scenario.wheel.scale_error);
  std::printf("lever error %.4f %.4f %.4f m (std %.4f %.4f %.4f); mounting error pitch %.4f yaw %.4f deg (std %.4f %.4f); "
              "time offset error %.3f ms (std %.3f); odometer scale error %.5f %% (std %.5f); %s\n",
              lever_err.x(), lever_err.y(), lever_err.z(), r.gnss_lever_arm_m.std.x(), r.gnss_lever_arm_m.std.y(),
              r.gnss_lever_arm_m.std.z(), mount_err_deg.y(), mount_err_deg.z(), r.mounting_rpy_rad.std.y() * rot::kRadToDeg,
              r.mounting_rpy_rad.std.z() * rot::kRadToDeg, dt_err_s * 1e3, r.imu_time_offset_s.std * 1e3, scale_err * 100.0,
              r.odometer_scale->std * 100.0, r.message.c_str());
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(std::abs(lever_err[i]), 0.02) << "axis " << i;
    EXPECT_LT(std::abs(lever_err[i]), kSigmas * r.gnss_lever_arm_m.std[i]) << "axis " << i;
  }
  EXPECT_NEAR(mount_err_deg.x(), 0.0, 1e-9);  // roll is held at the configured (true) value
  for (int i = 1; i < 3; ++i) {
    EXPECT_LT(std::abs(mount_err_deg[i]), 0.1) << "angle " << i;
    EXPECT_LT(std::abs(mount_err_deg[i]), kSigmas * r.mounting_rpy_rad.std[i] * rot::kRadToDeg) << "angle " << i;
  }
  EXPECT_LT(std::abs(dt_err_s), 0.002);
  EXPECT_LT(std::abs(dt_err_s), kSigmas * r.imu_time_offset_s.std);
  EXPECT_LT(std::abs(scale_err), 0.001);
  EXPECT_LT(std::abs(scale_err), kSigmas * r.odometer_scale->std);
  // The turn-on biases are found too (a drive is long enough for them, not for their drift).
  const sim::SimulationOutput head = sim::simulate([&] {
    sim::Scenario first = scenario;
    first.trajectory.segments.resize(1);
    return first;
  }());
  const Eigen::Matrix3d c_sv = rot::dcm_from_rpy(scenario.imu.mounting_rpy_deg * rot::kDegToRad).transpose();
  const Eigen::Vector3d true_gyro_bias = c_sv * head.truth.back().gyro_bias_vehicle_rps;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.gyro_bias_rps.value[i], true_gyro_bias[i], 5.0 * rot::kDegToRad / 3600.0) << "axis " << i;
  }
  EXPECT_LT(r.position_rms_m, 0.06);  // RTK: 2 cm horizontal, 3 cm vertical per axis
}

// A dual-antenna receiver and no odometry (not a land vehicle: no NHC either): the heading alone
// sees the mounting's yaw, the angle between the baseline the receiver measures and the axes the
// IMU turns. The baseline, 1.5 m at 36.9 deg to the vehicle's x axis, is configured right.
TEST(CalibrationProblem, ADualAntennaHeadingFindsTheMountingYawWithoutOdometry) {
  sim::Scenario scenario = sim::make_scenario("calibration_drive");
  scenario.gnss.heading = true;
  scenario.gnss.secondary_lever_arm_m = scenario.gnss.lever_arm_m + Eigen::Vector3d(1.2, 0.9, 0.0);
  const testing::StartingSetup start{.lever_arm_m = scenario.gnss.lever_arm_m + Eigen::Vector3d(0.3, -0.2, 0.4),
                                     .mounting_rpy_deg = Eigen::Vector3d(scenario.imu.mounting_rpy_deg.x(), 0.0, 0.0),
                                     .imu_time_offset_s = 0.0};
  testing::SimLog s = testing::sim_log(scenario, start);
  s.log.setup.land_vehicle = false;
  s.log.speeds.clear();
  ASSERT_FALSE(s.log.headings.empty());
  const CalibrationResult r = calibrate(s.log);
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_TRUE(r.covariance_ok) << r.message;
  ASSERT_TRUE(r.mounting_estimated);
  EXPECT_GT(r.gnss_heading_residuals, s.log.headings.size() / 2);
  EXPECT_EQ(r.speed_residuals + r.nhc_residuals, 0u);
  const double yaw_err_deg = r.mounting_rpy_rad.value.z() * rot::kRadToDeg - scenario.imu.mounting_rpy_deg.z();
  const double yaw_std_deg = r.mounting_rpy_rad.std.z() * rot::kRadToDeg;
  const double dt_err_s = r.imu_time_offset_s.value - scenario.imu.time_offset_s;
  std::printf("%zu headings: mounting yaw error %.4f deg (std %.4f), time offset error %.3f ms (std %.3f); %s\n",
              s.log.headings.size(), yaw_err_deg, yaw_std_deg, dt_err_s * 1e3, r.imu_time_offset_s.std * 1e3,
              r.message.c_str());
  EXPECT_LT(std::abs(yaw_err_deg), 0.1);
  EXPECT_LT(std::abs(yaw_err_deg), kSigmas * yaw_std_deg);
  EXPECT_LT(std::abs(dt_err_s), 0.002);
  EXPECT_LT(std::abs(dt_err_s), kSigmas * r.imu_time_offset_s.std);
  // The same log without the headings: nothing sees the mounting, which stays as configured.
  s.log.headings.clear();
  const CalibrationResult without = calibrate(s.log);
  EXPECT_FALSE(without.mounting_estimated);
  EXPECT_NEAR(without.mounting_rpy_rad.value.z(), 0.0, 1e-12);
}

TEST(CalibrationProblem, NothingToCalibrateSaysWhy) {
  CalibrationLog empty;
  const CalibrationResult r = calibrate(empty);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.epochs, 0u);
  EXPECT_FALSE(r.message.empty());
}

}  // namespace
}  // namespace navfuse::calib

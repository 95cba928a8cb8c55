// The calibration on a simulated drive with a known installation (sim calibration_drive: RTK GNSS
// at 10 Hz, industrial IMU with its noise, biases and scale factors, mounted at roll 0.3, pitch
// 1.5, yaw -2.0 deg, its clock 50 ms behind GPS time, 0.5 % odometer scale error, antenna at
// (0.8, -0.4, -1.3) m), starting from a configuration that is wrong in all of them but roll.
// The starting trajectory is the truth on the configured clock (what the smoother gives is
// tested end to end in tests/apps/calibration_scenario_test.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "calibration/calibration_problem.hpp"
#include "core/geodesy/geodesy.hpp"
#include "sim_log.hpp"

namespace navfuse::calib {
namespace {

constexpr double kSigmas = 3.0;  // a reported std dev "covers" an error within this many

// The receiver's fixes given again as external LLH positions at the antenna's lever arm (as
// `navfuse aid` feeds them), their reported std devs per axis.
void add_fixes_as_external_positions(CalibrationLog& log, const Eigen::Vector3d& lever_arm_m) {
  for (const GnssPosition& p : log.positions) {
    if ((p.header.valid & GnssPosition::kValidPosition) == 0 || p.fix == GnssFixType::kNone) continue;
    ExternalPosition e;
    e.header = p.header;
    e.header.valid = ExternalPosition::kValidX | ExternalPosition::kValidY | ExternalPosition::kValidZ;
    e.value = Eigen::Vector3d(p.lat_rad, p.lon_rad, p.height_m);
    e.std_m = p.cov_ned_m2.diagonal().cwiseSqrt();
    e.lever_arm_m = lever_arm_m;
    log.external_positions.push_back(e);
  }
}

// The installation of `scenario` recovered within the goals and covered by its std devs.
void expect_installation_recovered(const sim::Scenario& scenario) {
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

TEST(CalibrationProblem, RecoversSimulatedInstallation) {
  expect_installation_recovered(sim::make_scenario("calibration_drive"));
}

// A car that does not slip at its rear axle (the odometer's point, 1.2 m behind the IMU), the NHC
// there: the IMU's own sideways velocity in turns is not an error to explain away with the mounting.
TEST(CalibrationProblem, RecoversSimulatedInstallationOfACarThatDoesNotSlipAtItsRearAxle) {
  sim::Scenario scenario = sim::make_scenario("calibration_drive");
  scenario.trajectory.nonslip_point_m = scenario.wheel.lever_arm_m;
  expect_installation_recovered(scenario);
}

// The same car with a config that does not say where it does not slip: the constraint's point is
// the IMU, a guess known to (1.5, 0.5, 0.5) m (nhc.lever_arm_std_m's default then). The turns show
// the IMU's sideways velocity as yaw rate x the point's x; the calibration finds the rear axle.
TEST(CalibrationProblem, FindsWhereACarDoesNotSlipWhenTheConfigOnlyGuesses) {
  sim::Scenario scenario = sim::make_scenario("calibration_drive");
  scenario.trajectory.nonslip_point_m = scenario.wheel.lever_arm_m;  // (-1.2, 0, 0.3)
  const testing::StartingSetup start{.lever_arm_m = scenario.gnss.lever_arm_m + Eigen::Vector3d(0.3, -0.2, 0.4),
                                     .mounting_rpy_deg = Eigen::Vector3d(scenario.imu.mounting_rpy_deg.x(), 0.0, 0.0),
                                     .imu_time_offset_s = 0.0};
  testing::SimLog s = testing::sim_log(scenario, start);
  s.log.setup.nhc_lever_arm_m = Eigen::Vector3d::Zero();
  s.log.setup.nhc_lever_arm_std_m = Eigen::Vector3d(1.5, 0.5, 0.5);
  const CalibrationResult r = calibrate(s.log);
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_TRUE(r.covariance_ok) << r.message;
  ASSERT_TRUE(r.nhc_lever_arm_estimated);
  const Eigen::Vector3d err = r.nhc_lever_arm_m.value - scenario.trajectory.nonslip_point_m;
  std::printf("non-slip point %.3f %.3f %.3f m (std %.3f %.3f %.3f); GNSS lever error %.4f %.4f %.4f m; "
              "yaw error %.4f deg; offset error %.3f ms\n",
              r.nhc_lever_arm_m.value.x(), r.nhc_lever_arm_m.value.y(), r.nhc_lever_arm_m.value.z(),
              r.nhc_lever_arm_m.std.x(), r.nhc_lever_arm_m.std.y(), r.nhc_lever_arm_m.std.z(),
              r.gnss_lever_arm_m.value.x() - scenario.gnss.lever_arm_m.x(),
              r.gnss_lever_arm_m.value.y() - scenario.gnss.lever_arm_m.y(),
              r.gnss_lever_arm_m.value.z() - scenario.gnss.lever_arm_m.z(),
              r.mounting_rpy_rad.value.z() * rot::kRadToDeg - scenario.imu.mounting_rpy_deg.z(),
              (r.imu_time_offset_s.value - scenario.imu.time_offset_s) * 1e3);
  EXPECT_LT(std::abs(err.x()), 0.05);
  EXPECT_LT(std::abs(err.x()), kSigmas * r.nhc_lever_arm_m.std.x());
  EXPECT_LT(r.nhc_lever_arm_m.std.x(), 0.05);
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(r.gnss_lever_arm_m.value[i] - scenario.gnss.lever_arm_m[i]), 0.02) << i;
  EXPECT_LT(std::abs(r.mounting_rpy_rad.value.z() * rot::kRadToDeg - scenario.imu.mounting_rpy_deg.z()), 0.1);
  EXPECT_LT(std::abs(r.imu_time_offset_s.value - scenario.imu.time_offset_s), 0.002);
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

// The same installation seen through external aiding only (MIP 0x13 semantics, as `navfuse aid`
// feeds it): the receiver's fixes as LLH positions at the antenna's lever arm, its velocities in
// ECEF axes, its heading turned into the vehicle's. No GNSS measurement, no odometry: the
// external heading sees the mounting's yaw, positions and velocities the clock offset.
TEST(CalibrationProblem, ExternalAidingAloneFindsTheMountingYawAndTheOffset) {
  sim::Scenario scenario = sim::make_scenario("calibration_drive");
  scenario.gnss.heading = true;
  // Along the vehicle's x axis: the baseline's azimuth is then the vehicle's heading (the ZYX yaw)
  // at any roll and pitch, so the receiver's headings are external headings as they are.
  const Eigen::Vector3d baseline_v(1.5, 0.0, 0.0);
  scenario.gnss.secondary_lever_arm_m = scenario.gnss.lever_arm_m + baseline_v;
  const testing::StartingSetup start{.lever_arm_m = scenario.gnss.lever_arm_m,
                                     .mounting_rpy_deg = Eigen::Vector3d(scenario.imu.mounting_rpy_deg.x(), 0.0, 0.0),
                                     .imu_time_offset_s = 0.0};
  testing::SimLog s = testing::sim_log(scenario, start);
  CalibrationLog& log = s.log;
  log.setup.land_vehicle = false;
  log.speeds.clear();
  add_fixes_as_external_positions(log, scenario.gnss.lever_arm_m);
  for (const GnssVelocity& v : log.velocities) {
    if ((v.header.valid & GnssVelocity::kValidVelocity) == 0) continue;
    // Isotropic in ECEF: the receiver's NED covariance's largest variance on every axis.
    ExternalVelocity e;
    e.header = v.header;
    e.header.valid = ExternalVelocity::kValidX | ExternalVelocity::kValidY | ExternalVelocity::kValidZ;
    e.frame = VelocityFrame::kEcef;
    const GnssPosition& near = *std::min_element(log.positions.begin(), log.positions.end(),
                                                 [&](const GnssPosition& a, const GnssPosition& b) {
                                                   return std::llabs(a.header.time_ns - v.header.time_ns) <
                                                          std::llabs(b.header.time_ns - v.header.time_ns);
                                                 });
    e.value_mps = geo::rot_ecef_from_ned(near.lat_rad, near.lon_rad) * v.vel_ned_mps;
    e.std_mps = Eigen::Vector3d::Constant(std::sqrt(v.cov_ned_m2ps2.diagonal().maxCoeff()));
    e.lever_arm_m = scenario.gnss.lever_arm_m;
    log.external_velocities.push_back(e);
  }
  for (const GnssHeading& h : log.headings) {
    if ((h.header.valid & GnssHeading::kValidHeading) == 0) continue;
    log.external_headings.push_back({.header = h.header, .heading_rad = h.heading_rad, .std_rad = h.heading_std_rad});
    log.external_headings.back().header.valid = ExternalHeading::kValidHeading;
  }
  // Every one inside the smoothed trajectory's span is used (sim_log's starts 30 s in).
  const auto in_span = [&](const auto& m) {
    return m.header.time_ns >= log.trajectory.front().time_ns && m.header.time_ns <= log.trajectory.back().time_ns;
  };
  const auto external = static_cast<std::uint64_t>(
      std::count_if(log.external_positions.begin(), log.external_positions.end(), in_span) +
      std::count_if(log.external_velocities.begin(), log.external_velocities.end(), in_span) +
      std::count_if(log.external_headings.begin(), log.external_headings.end(), in_span));
  log.positions.clear();
  log.velocities.clear();
  log.headings.clear();
  const CalibrationResult r = calibrate(log);
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_TRUE(r.covariance_ok) << r.message;
  ASSERT_TRUE(r.mounting_estimated);
  EXPECT_EQ(r.gnss_position_residuals + r.gnss_velocity_residuals + r.gnss_heading_residuals, 0u);
  EXPECT_EQ(r.external_residuals, external);
  const double yaw_err_deg = r.mounting_rpy_rad.value.z() * rot::kRadToDeg - scenario.imu.mounting_rpy_deg.z();
  const double yaw_std_deg = r.mounting_rpy_rad.std.z() * rot::kRadToDeg;
  const double dt_err_s = r.imu_time_offset_s.value - scenario.imu.time_offset_s;
  std::printf("%llu external residuals: mounting yaw error %.4f deg (std %.4f), time offset error %.3f ms (std %.3f); %s\n",
              static_cast<unsigned long long>(r.external_residuals), yaw_err_deg, yaw_std_deg, dt_err_s * 1e3,
              r.imu_time_offset_s.std * 1e3, r.message.c_str());
  EXPECT_LT(std::abs(yaw_err_deg), 0.1);
  EXPECT_LT(std::abs(yaw_err_deg), kSigmas * yaw_std_deg);
  EXPECT_LT(std::abs(dt_err_s), 0.002);
  EXPECT_LT(std::abs(dt_err_s), kSigmas * r.imu_time_offset_s.std);
  // The GNSS lever arm has no measurement: it comes back at its prior.
  EXPECT_NEAR(r.gnss_lever_arm_m.std.x(), CalibrationOptions{}.lever_arm_prior_std_m, 1e-3);
}

// A body-frame velocity aid (MIP (0x13,0x2A): a radar or a visual odometer) with external
// positions and nothing else: no odometry, no NHC, no heading. Its sideways and vertical
// components see the mounting's yaw and pitch as the NHC does. Made from the truth at 10 Hz with
// 5 cm/s of white noise per axis, at the IMU (lever arm zero).
TEST(CalibrationProblem, AVehicleFrameVelocityAidFindsTheMounting) {
  const sim::Scenario scenario = sim::make_scenario("calibration_drive");
  const testing::StartingSetup start{.lever_arm_m = scenario.gnss.lever_arm_m,
                                     .mounting_rpy_deg = Eigen::Vector3d(scenario.imu.mounting_rpy_deg.x(), 0.0, 0.0),
                                     .imu_time_offset_s = 0.0};
  testing::SimLog s = testing::sim_log(scenario, start);
  CalibrationLog& log = s.log;
  log.setup.land_vehicle = false;
  log.speeds.clear();
  add_fixes_as_external_positions(log, scenario.gnss.lever_arm_m);
  std::mt19937_64 rng(16);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (std::size_t i = 0; i < log.trajectory.size(); i += 20) {  // the truth (configured offset zero)
    const TrajectoryPoint& t = log.trajectory[i];
    ExternalVelocity e;
    e.header.time_ns = t.time_ns;
    e.header.valid = ExternalVelocity::kValidX | ExternalVelocity::kValidY | ExternalVelocity::kValidZ;
    e.frame = VelocityFrame::kVehicle;
    e.value_mps = t.q_nv.conjugate() * t.vel_ned_mps + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    e.std_mps = Eigen::Vector3d::Constant(0.05);
    log.external_velocities.push_back(e);
  }
  log.positions.clear();
  log.velocities.clear();
  const CalibrationResult r = calibrate(log);
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_TRUE(r.covariance_ok) << r.message;
  ASSERT_TRUE(r.mounting_estimated);
  EXPECT_EQ(r.speed_residuals + r.nhc_residuals + r.gnss_heading_residuals, 0u);
  const Eigen::Vector3d mount_err_deg = r.mounting_rpy_rad.value * rot::kRadToDeg - scenario.imu.mounting_rpy_deg;
  const double dt_err_s = r.imu_time_offset_s.value - scenario.imu.time_offset_s;
  std::printf("%llu external residuals: mounting error pitch %.4f yaw %.4f deg (std %.4f %.4f), time offset error "
              "%.3f ms (std %.3f); %s\n",
              static_cast<unsigned long long>(r.external_residuals), mount_err_deg.y(), mount_err_deg.z(),
              r.mounting_rpy_rad.std.y() * rot::kRadToDeg, r.mounting_rpy_rad.std.z() * rot::kRadToDeg, dt_err_s * 1e3,
              r.imu_time_offset_s.std * 1e3, r.message.c_str());
  for (int i = 1; i < 3; ++i) {
    EXPECT_LT(std::abs(mount_err_deg[i]), 0.1) << "angle " << i;
    EXPECT_LT(std::abs(mount_err_deg[i]), kSigmas * r.mounting_rpy_rad.std[i] * rot::kRadToDeg) << "angle " << i;
  }
  EXPECT_LT(std::abs(dt_err_s), 0.002);
  EXPECT_LT(std::abs(dt_err_s), kSigmas * r.imu_time_offset_s.std);
  // Without the velocity aid nothing sees the mounting.
  log.external_velocities.clear();
  const CalibrationResult without = calibrate(log);
  EXPECT_FALSE(without.mounting_estimated);
}

// Biases that drift (calibration/bias_segments.hpp): calibration_drive with a gyro and an
// accelerometer whose bias instability is far above the industrial grade's and wanders within a
// minute (Gauss-Markov 30 deg/h and 1 mg, 60 s), the configured drift the simulated one. Measured
// (2026-11-29): one bias over the log puts the lever arm 13 cm off in x and z and the mounting
// pitch 0.12 deg off, 9-10 std devs each; segments of 60 s still leave y 5 cm off (11 std), 20 s
// x 2.5 cm (2.7), 10 s (the default) every error inside its std devs and its goal but z (4.6 cm,
// std 3.4: this drive does not see z better, README).
TEST(CalibrationProblem, DriftingBiasesAreFollowedSegmentBySegment) {
  sim::Scenario scenario = sim::make_scenario("calibration_drive");
  sim::ImuErrorSpec& e = scenario.imu.errors;
  e.gyro_bias_instability_deg_hr = 30.0;
  e.gyro_bias_corr_time_s = 60.0;
  e.accel_bias_instability_mps2 = 1e-3 * 9.80665;
  e.accel_bias_corr_time_s = 60.0;
  const testing::StartingSetup start{.lever_arm_m = scenario.gnss.lever_arm_m + Eigen::Vector3d(0.3, -0.2, 0.4),
                                     .mounting_rpy_deg = Eigen::Vector3d(scenario.imu.mounting_rpy_deg.x(), 0.0, 0.0),
                                     .imu_time_offset_s = 0.0};
  testing::SimLog s = testing::sim_log(scenario, start);
  // The drift's random-walk densities (q = sqrt(2 sigma^2 / tau)), as calibration_collector.cpp
  // makes them from the imu: config keys.
  s.log.setup.gyro_bias_std_rps = e.gyro_bias_instability_deg_hr * rot::kDegToRad / 3600.0 * std::sqrt(2.0 / 60.0);
  s.log.setup.accel_bias_std_mps2 = e.accel_bias_instability_mps2 * std::sqrt(2.0 / 60.0);

  const CalibrationResult r = calibrate(s.log);
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_TRUE(r.covariance_ok) << r.message;
  const Eigen::Vector3d lever_err = r.gnss_lever_arm_m.value - scenario.gnss.lever_arm_m;
  const Eigen::Vector3d mount_err_deg = r.mounting_rpy_rad.value * rot::kRadToDeg - scenario.imu.mounting_rpy_deg;
  const double dt_err_s = r.imu_time_offset_s.value - scenario.imu.time_offset_s;
  std::printf("%zu bias segments: lever error %.4f %.4f %.4f m (std %.4f %.4f %.4f); mounting error pitch %.4f yaw "
              "%.4f deg (std %.4f %.4f); offset error %.3f ms (std %.3f); %.1f s\n",
              r.bias_segments.size(), lever_err.x(), lever_err.y(), lever_err.z(), r.gnss_lever_arm_m.std.x(),
              r.gnss_lever_arm_m.std.y(), r.gnss_lever_arm_m.std.z(), mount_err_deg.y(), mount_err_deg.z(),
              r.mounting_rpy_rad.std.y() * rot::kRadToDeg, r.mounting_rpy_rad.std.z() * rot::kRadToDeg, dt_err_s * 1e3,
              r.imu_time_offset_s.std * 1e3, r.wall_s);
  EXPECT_GT(r.bias_segments.size(), 10u);
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(lever_err[i]), kSigmas * r.gnss_lever_arm_m.std[i]) << "axis " << i;
  EXPECT_LT(std::abs(lever_err.x()), 0.02);
  EXPECT_LT(std::abs(lever_err.y()), 0.02);
  for (int i = 1; i < 3; ++i) {
    EXPECT_LT(std::abs(mount_err_deg[i]), 0.1) << "angle " << i;
    EXPECT_LT(std::abs(mount_err_deg[i]), kSigmas * r.mounting_rpy_rad.std[i] * rot::kRadToDeg) << "angle " << i;
  }
  EXPECT_LT(std::abs(dt_err_s), 0.002);
  EXPECT_LT(std::abs(dt_err_s), kSigmas * r.imu_time_offset_s.std);

  // Each segment against the simulated bias over it (sensor frame): its mean there, with the
  // spread the bias has inside the segment (a constant cannot do better) added to the estimate's
  // std dev. The accelerometer's z is left out: on a drive it always reads about -g, so its bias
  // and its scale factor are one number.
  const Eigen::Matrix3d c_sv = rot::dcm_from_rpy(scenario.imu.mounting_rpy_deg * rot::kDegToRad).transpose();
  for (std::size_t k = 0; k < r.bias_segments.size(); ++k) {
    const std::int64_t from = r.bias_segments[k].start_ns;
    const std::int64_t to = k + 1 < r.bias_segments.size() ? r.bias_segments[k + 1].start_ns : s.log.imu.back().header.time_ns;
    std::vector<Eigen::Vector3d> bg, ba;
    for (const TrajectoryPoint& t : s.log.trajectory) {
      if (t.time_ns < from || t.time_ns >= to) continue;
      bg.push_back(c_sv * t.gyro_bias_v_rps);
      ba.push_back(c_sv * t.accel_bias_v_mps2);
    }
    ASSERT_FALSE(bg.empty());
    auto mean_and_spread = [](const std::vector<Eigen::Vector3d>& v, Eigen::Vector3d& mean, Eigen::Vector3d& spread) {
      mean.setZero();
      for (const Eigen::Vector3d& x : v) mean += x / static_cast<double>(v.size());
      spread.setZero();
      for (const Eigen::Vector3d& x : v) spread += (x - mean).cwiseAbs2() / static_cast<double>(v.size());
      spread = spread.cwiseSqrt();
    };
    Eigen::Vector3d bg_mean, bg_spread, ba_mean, ba_spread;
    mean_and_spread(bg, bg_mean, bg_spread);
    mean_and_spread(ba, ba_mean, ba_spread);
    const CalibrationResult::BiasSegment& seg = r.bias_segments[k];
    for (int i = 0; i < 3; ++i) {
      const double gyro_tol = kSigmas * std::hypot(seg.gyro_bias_rps.std[i], bg_spread[i]);
      EXPECT_NEAR(seg.gyro_bias_rps.value[i], bg_mean[i], gyro_tol) << "segment " << k << " gyro axis " << i;
      if (i == 2) continue;
      const double accel_tol = kSigmas * std::hypot(seg.accel_bias_mps2.std[i], ba_spread[i]);
      EXPECT_NEAR(seg.accel_bias_mps2.value[i], ba_mean[i], accel_tol) << "segment " << k << " accel axis " << i;
    }
  }

  // One bias over the log: the drift goes into the installation.
  CalibrationOptions constant;
  constant.bias_segments.length_s = 0.0;
  const CalibrationResult one = calibrate(s.log, constant);
  ASSERT_EQ(one.bias_segments.size(), 1u);
  const Eigen::Vector3d one_lever_err = one.gnss_lever_arm_m.value - scenario.gnss.lever_arm_m;
  std::printf("one bias: lever error %.4f %.4f %.4f m (std %.4f %.4f %.4f)\n", one_lever_err.x(), one_lever_err.y(),
              one_lever_err.z(), one.gnss_lever_arm_m.std.x(), one.gnss_lever_arm_m.std.y(), one.gnss_lever_arm_m.std.z());
  EXPECT_GT(std::abs(one_lever_err.x()), kSigmas * one.gnss_lever_arm_m.std.x());
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

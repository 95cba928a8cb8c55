// End-to-end `navfuse smooth --calibration-out` on the simulated calibration drive (sim
// calibration_drive as a VN-300 log with its vehicle speed in a FusionEngine log), from a
// configuration whose lever arm, mounting pitch/yaw and IMU time offset are wrong: the calibration
// recovers the simulator's installation, the file it writes loads as a config with those values,
// and the summary carries the table. Label "scenario".
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "apps/replay/calibration_hook.hpp"
#include "apps/replay/replay.hpp"
#include "apps/sim/scenarios.hpp"
#include "apps/simcmd/sim_command.hpp"
#include "calibration/calibration_problem.hpp"
#include "core/config/config.hpp"
#include "core/rotation/rotation.hpp"
#include "parking_drive_log.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

double parameter(const nlohmann::ordered_json& calibration, const std::string& name, const char* what) {
  return calibration.at("parameters").at(name).at(what).get<double>();
}

TEST(CalibrationScenario, SmoothRecoversTheSimulatedInstallation) {
  set_calibration_solver([](const calib::CalibrationLog& log) { return calib::calibrate(log); });
  const std::filesystem::path dir = testing::scratch_dir();
  SimOptions sim;
  sim.scenario = "calibration_drive";
  sim.format = "vn";
  sim.out_path = (dir / "vn.bin").string();
  sim.wheel_out_path = (dir / "wheel.p1log").string();
  run_sim(sim);
  const sim::Scenario truth = sim::make_scenario("calibration_drive");

  // The demo's VN-300 config, wrong where the calibration should put it right (roll is held).
  config::Config start = config::load_from_file(std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/vn300.yaml");
  start.gnss.lever_arm_m = {0.5, -0.2, -1.0};
  start.imu.mounting_rpy_deg = {truth.imu.mounting_rpy_deg.x(), 0.0, 0.0};
  start.imu.time_offset_s = 0.0;
  std::ofstream(dir / "start.yaml") << config::to_yaml(start);

  ReplayOptions o;
  o.config_path = (dir / "start.yaml").string();
  o.inputs = {sim.out_path, sim.wheel_out_path};
  o.smooth = true;
  o.calibration_out = (dir / "calib.yaml").string();
  const ReplayResult result = run_replay(o);
  ASSERT_TRUE(result.failure.empty()) << result.failure;
  std::printf("%s", result.calibration_text.c_str());
  ASSERT_NE(result.calibration_text.find("gnss.lever_arm_m x"), std::string::npos);
  const nlohmann::ordered_json& c = result.summary.extra.at("batch_calibration");
  EXPECT_TRUE(c.at("converged").get<bool>());
  EXPECT_TRUE(c.at("covariance_ok").get<bool>());

  // Estimates against the simulator's installation, each within its std dev's 3-sigma.
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    const std::string name = std::string("gnss.lever_arm_m ") + axes[i];
    const double err = parameter(c, name, "estimate") - truth.gnss.lever_arm_m[i];
    EXPECT_LT(std::abs(err), 3.0 * parameter(c, name, "std")) << name;
    // The vertical is seen only while the vehicle tilts (climbs, camber): a few cm on this drive.
    EXPECT_LT(std::abs(err), i < 2 ? 0.02 : 0.05) << name;
  }
  const char* angles[] = {"pitch", "yaw"};
  for (int i = 0; i < 2; ++i) {
    const std::string name = std::string("imu.mounting_rpy_deg ") + angles[i];
    const double err = parameter(c, name, "estimate") - truth.imu.mounting_rpy_deg[i + 1];
    EXPECT_LT(std::abs(err), 0.1) << name;
    EXPECT_LT(std::abs(err), 3.0 * parameter(c, name, "std")) << name;
  }
  const double dt_err_ms = parameter(c, "imu.time_offset_s", "estimate") - truth.imu.time_offset_s * 1e3;
  EXPECT_LT(std::abs(dt_err_ms), 2.0);
  EXPECT_LT(std::abs(dt_err_ms), 3.0 * parameter(c, "imu.time_offset_s", "std"));
  const double scale_err_pct = parameter(c, "odometer scale (measured/true)", "estimate") - truth.wheel.scale_error * 100.0;
  EXPECT_LT(std::abs(scale_err_pct), 0.1);
  EXPECT_LT(std::abs(scale_err_pct), 3.0 * parameter(c, "odometer scale (measured/true)", "std"));

  // The file is a config that loads, with the calibrated keys and everything else as started.
  const config::Config back = config::load_from_file(o.calibration_out);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(back.gnss.lever_arm_m[static_cast<std::size_t>(i)],
                parameter(c, std::string("gnss.lever_arm_m ") + axes[i], "estimate"), 1e-4);
  }
  EXPECT_NEAR(back.imu.mounting_rpy_deg[1], parameter(c, "imu.mounting_rpy_deg pitch", "estimate"), 1e-4);
  EXPECT_NEAR(back.imu.mounting_rpy_deg[2], parameter(c, "imu.mounting_rpy_deg yaw", "estimate"), 1e-4);
  EXPECT_NEAR(back.imu.time_offset_s * 1e3, parameter(c, "imu.time_offset_s", "estimate"), 1e-2);
  EXPECT_EQ(back.imu.mounting_rpy_deg[0], start.imu.mounting_rpy_deg[0]);
  EXPECT_EQ(back.wheel.lever_arm_m, start.wheel.lever_arm_m);
  EXPECT_EQ(back.imu.gyro_arw_deg_rthr, start.imu.gyro_arw_deg_rthr);
  std::ifstream in(o.calibration_out);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("#   imu.time_offset_s: "), std::string::npos);  // std devs in comments
  // Written as rounded, to the 10 us it is rounded to: "time_offset_s: 0.04991", not the binary
  // neighbour's 0.049910000000000003.
  const std::string key = "\n  time_offset_s: ";
  const std::size_t at = text.str().find(key);
  ASSERT_NE(at, std::string::npos);
  const std::string value = text.str().substr(at + key.size(), text.str().find_first_of(" \n", at + key.size()) - at - key.size());
  EXPECT_LE(value.size(), 8u) << value;
}

// Issue 16's held-out check, on the drive built from issue 14's description of it (sim
// parking_drive: tight car-park corners, 4 Hz RTK, an ADIS16465-class IMU at 100 Hz with car
// vibration, its clock 125 ms behind GNSS, no odometer): the config has the IMU's data-sheet noise
// and no time offset; the calibration must find the 125 ms within 5 ms. One round stops short
// (-119.2 ms, 2026-11-24: the smoothed trajectory it starts from was made with the offset
// missing, heading 2 deg RMS off; before the IMU noise re-weighting, -98.9 ms); the second, from
// the first round's installation, gets there (-128.6 +- 3.2 ms, 2026-11-29).
// Six draws (seeds 27, 1-5, two rounds, 2026-11-29) are off by -3.6, +0.8, +3.0, -0.2, -0.2, +0.7 ms
// at std devs of 3.1 ms, with the IMU's white noise measured from its samples and the trajectory
// read continuously at each pass's offset (README, calibration); before those, -4.3, 11.6, -1.6,
// -3.8, 0.0, 6.9 ms at 1.1-1.3 ms, the std devs covering nothing. Without the vibration -0.8-0.9 ms
// at 0.8 ms. The std dev is now held to cover the error within three of it.
TEST(CalibrationScenario, TheParkingDrivesImuOffsetIsFoundInTwoRounds) {
  set_calibration_solver([](const calib::CalibrationLog& log) { return calib::calibrate(log); });
  const std::filesystem::path dir = testing::scratch_dir();
  const testing::ParkingDriveLog parking = testing::write_parking_drive(dir, std::nullopt);
  const sim::Scenario truth = sim::make_scenario("parking_drive");
  auto offset_error_ms = [&](int rounds, double* std_ms) {
    ReplayOptions o;
    o.config_path = parking.config_path;
    o.inputs = {parking.log_path};
    o.smooth = true;
    o.calibration_out = (dir / "calib.yaml").string();
    o.calibration_rounds = rounds;
    const ReplayResult result = run_replay(o);
    EXPECT_TRUE(result.failure.empty()) << result.failure;
    EXPECT_EQ(result.calibration_rounds, rounds);
    std::printf("%d round(s):\n%s", rounds, result.calibration_text.c_str());
    const nlohmann::ordered_json& c = result.summary.extra.at("batch_calibration");
    *std_ms = parameter(c, "imu.time_offset_s", "std");
    return parameter(c, "imu.time_offset_s", "estimate") - truth.imu.time_offset_s * 1e3;
  };
  double std_ms = 0.0;
  const double error_ms = offset_error_ms(2, &std_ms);
  EXPECT_LT(std::abs(error_ms), 5.0);
  EXPECT_GT(std_ms, 0.0);
  EXPECT_LT(std::abs(error_ms), 3.0 * std_ms);
}

// The same drive (another draw: seed 31) with positions only from the receiver (an RTKLIB .pos
// without velocity columns), its IMU mounted x right, z up (roll 180, yaw -90) as on the
// held-out car. The mounting is estimated about the vehicle's own axes: its pitch is what the
// NHC's vertical velocity sees. Estimated as the config key's Euler pitch instead (before
// 2026-11-25) the angle turned the vehicle frame about its x axis, which nothing sees: it went to
// 30.5 deg without a prior, to -3.1 +- 5.3 deg (the prior's) with one, and written back it put the
// reported roll 1.8 deg off. The time offset is left traded against the lever arm's x (README):
// printed, held only to 15 ms here.
TEST(CalibrationScenario, PositionsOnlyFindTheVehiclePitchOfASensorMountedXRightZUp) {
  set_calibration_solver([](const calib::CalibrationLog& log) { return calib::calibrate(log); });
  const std::filesystem::path dir = testing::scratch_dir();
  const testing::ParkingDriveLog parking = testing::write_parking_drive(dir, std::nullopt, false, 31);
  const sim::Scenario truth = sim::make_scenario("parking_drive");
  ReplayOptions o;
  o.config_path = parking.config_path;
  o.inputs = {parking.log_path};
  o.smooth = true;
  o.calibration_out = (dir / "calib.yaml").string();
  const ReplayResult result = run_replay(o);
  ASSERT_TRUE(result.failure.empty()) << result.failure;
  std::printf("%s", result.calibration_text.c_str());
  const nlohmann::ordered_json& c = result.summary.extra.at("batch_calibration");
  EXPECT_TRUE(c.at("converged").get<bool>());
  EXPECT_EQ(c.at("gnss_velocity_residuals").get<int>(), 0);
  // The simulated mounting is the configured one: both residuals are zero in truth.
  for (const char* name : {"mounting vehicle pitch residual", "mounting vehicle yaw residual"}) {
    const double value_deg = parameter(c, name, "estimate"), std_deg = parameter(c, name, "std");
    EXPECT_LT(std::abs(value_deg), 0.2) << name;
    EXPECT_GT(std_deg, 0.0) << name;
    EXPECT_LT(std_deg, 0.2) << name << ": observed, not the prior's 5 deg";
    EXPECT_LT(std::abs(value_deg), 3.0 * std_deg) << name;
  }
  // Written back, the mounting is the truth's rotation to within those 0.2 deg.
  const config::Config back = config::load_from_file(o.calibration_out);
  const Eigen::Matrix3d estimated = rot::dcm_from_rpy(
      Eigen::Vector3d(back.imu.mounting_rpy_deg[0], back.imu.mounting_rpy_deg[1], back.imu.mounting_rpy_deg[2]) *
      rot::kDegToRad);
  const Eigen::Matrix3d c_true = rot::dcm_from_rpy(truth.imu.mounting_rpy_deg * rot::kDegToRad);
  EXPECT_LT(Eigen::AngleAxisd(estimated * c_true.transpose()).angle() * rot::kRadToDeg, 0.2);
  EXPECT_LT(std::abs(parameter(c, "imu.time_offset_s", "estimate") - truth.imu.time_offset_s * 1e3), 15.0);
}

TEST(CalibrationScenario, CalibrationOutNeedsSmoothAndASolver) {
  ReplayOptions o;
  o.inputs = {std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/vn300.vnb"};
  o.config_path = std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/vn300.yaml";
  o.calibration_out = (testing::scratch_dir() / "calib.yaml").string();
  EXPECT_ANY_THROW(run_replay(o));  // replay, not smooth
}

}  // namespace
}  // namespace navfuse::apps

// Pose outputs: decimation grid, all-or-nothing files, CSV rows and the IMUOutput rebuilt from a
// solution, against hand-computed values.
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>

#include "apps/common/command_error.hpp"
#include "apps/output/csv_pose_writer.hpp"
#include "apps/output/fe_pose_writer.hpp"
#include "apps/output/output_file.hpp"
#include "apps/output/output_rate.hpp"
#include "core/rotation/rotation.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

using testing::read_text;
using testing::scratch_dir;

TEST(OutputRate, ZeroMeansEverySample) {
  OutputRate rate(0.0);
  for (int k = 0; k < 10; ++k) EXPECT_TRUE(rate.due(1'000'000'000LL + k * 5'000'000LL));
}

TEST(OutputRate, HundredHertzFromTwoHundredHertzIsEverySecondSample) {
  OutputRate rate(100.0);
  int due = 0;
  // 200 Hz samples at 5 ms on a whole-second grid: slots of 10 ms hold two samples each.
  for (int k = 0; k < 200; ++k) due += rate.due(7'000'000'000LL + k * 5'000'000LL) ? 1 : 0;
  EXPECT_EQ(due, 100);
}

TEST(OutputRate, FirstSampleAtOrAfterEachGridPoint) {
  OutputRate rate(10.0);  // 100 ms grid
  EXPECT_TRUE(rate.due(1'030'000'000));   // first sample: slot 10
  EXPECT_FALSE(rate.due(1'090'000'000));  // same slot
  EXPECT_TRUE(rate.due(1'100'000'000));   // on the grid point
  EXPECT_FALSE(rate.due(1'199'999'999));
  EXPECT_TRUE(rate.due(1'350'000'000));   // a gap skips slots, emits once
  EXPECT_FALSE(rate.due(1'360'000'000));
}

TEST(OutputFile, AppearsOnlyOnCommit) {
  const auto dir = scratch_dir();
  const auto path = dir / "out.bin";
  {
    OutputFile f(path.string());
    f.write(std::string_view("abc"));
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_TRUE(std::filesystem::exists(path.string() + ".partial"));
    f.commit();
  }
  EXPECT_EQ(read_text(path), "abc");
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
}

TEST(OutputFile, AbandonedFileLeavesNothing) {
  const auto dir = scratch_dir();
  const auto path = dir / "out.bin";
  try {
    OutputFile f(path.string());
    f.write(std::string_view("half"));
    throw std::runtime_error("run failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
}

TEST(OutputFile, UnwritableDirectoryIsACommandErrorNamingThePath) {
  try {
    OutputFile f("/nonexistent-dir/out.bin");
    FAIL() << "expected an error";
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/out.bin"), std::string::npos);
  }
}

TEST(CsvPoseWriter, RowHasExactTimeAndFixedDecimals) {
  const auto dir = scratch_dir();
  NavSolution s;
  s.header.time_ns = 1'234'567'890'000'000'005LL;  // exact ns must survive
  s.header.time_source = TimeSource::kGps;
  s.mode = NavMode::kNavigation;
  s.lat_rad = 45.0 * rot::kDegToRad;
  s.lon_rad = -120.5 * rot::kDegToRad;
  s.height_m = 100.25;
  s.vel_ned_mps = {1.0, -2.0, 0.5};
  s.rpy_rad = Eigen::Vector3d(1.0, -2.0, 90.0) * rot::kDegToRad;
  s.pos_std_ned_m = {0.5, 0.5, 1.0};
  s.vel_std_ned_mps = {0.01, 0.02, 0.03};
  s.att_std_rpy_rad = Eigen::Vector3d(0.1, 0.1, 0.5) * rot::kDegToRad;
  {
    CsvPoseWriter w((dir / "p.csv").string());
    w.on_pose(PoseEpoch{s});
    w.commit();
  }
  const std::string text = read_text(dir / "p.csv");
  const std::string row = text.substr(text.find('\n') + 1);
  EXPECT_EQ(row,
            "1234567890.000000005,gps,navigation,45.0000000000,-120.5000000000,100.2500,1.00000,-2.00000,"
            "0.50000,1.000000,-2.000000,90.000000,0.5000,0.5000,1.0000,0.01000,0.02000,0.03000,0.100000,"
            "0.100000,0.500000\n");
}

TEST(CompensatedImu, SpecificForceIsAccelerationMinusGravityInBody) {
  NavSolution s;
  s.header.valid = NavSolution::kValidAttitude;
  s.header.time_ns = 42;
  // Rolled 90 deg right: body y points down, so gravity (0, 0, g) in NED is (0, g, 0) in body.
  s.q_nb = rot::quat_from_rpy(Eigen::Vector3d(rot::kPi / 2, 0.0, 0.0));
  s.gravity_ned_mps2 = {0.0, 0.0, 9.8};
  s.linear_accel_mps2 = {1.0, 0.0, 0.0};
  s.angular_rate_rps = {0.1, 0.2, 0.3};
  ImuSample imu;
  ASSERT_TRUE(compensated_imu_from(s, imu));
  EXPECT_NEAR(imu.accel.x(), 1.0, 1e-12);
  EXPECT_NEAR(imu.accel.y(), -9.8, 1e-12);
  EXPECT_NEAR(imu.accel.z(), 0.0, 1e-12);
  EXPECT_EQ(imu.gyro, s.angular_rate_rps);
  EXPECT_EQ(imu.frame, SensorFrame::kVehicle);
  EXPECT_EQ(imu.quantity, ImuQuantity::kRates);
  EXPECT_EQ(imu.header.time_ns, 42);
}

TEST(CompensatedImu, NoAttitudeNoSample) {
  NavSolution s;
  ImuSample imu;
  EXPECT_FALSE(compensated_imu_from(s, imu));
}

}  // namespace
}  // namespace navfuse::apps

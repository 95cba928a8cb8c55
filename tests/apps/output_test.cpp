// Outputs: decimation grid, CSV rows, the IMUOutput rebuilt from a
// solution (against hand-computed values), and what the epoch encoders send at which epoch
// (against the DESIGN.md --fe-out / --mip-out contract).
#include <cmath>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "apps/common/summary.hpp"
#include "apps/output/compensated_imu.hpp"
#include "apps/output/csv_pose_writer.hpp"
#include "apps/output/encoded_file_writer.hpp"
#include "apps/output/fe_epoch_encoder.hpp"
#include "apps/output/mip_epoch_encoder.hpp"
#include "apps/output/output_rate.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/mip/framer.hpp"
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
  s.header.valid = NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
                   NavSolution::kValidHeading | NavSolution::kValidPositionStd | NavSolution::kValidVelocityStd |
                   NavSolution::kValidAttitudeStd;
  // Levelled, no GNSS yet, heading unknown: only roll, pitch and the attitude stds are known.
  NavSolution levelled = s;
  levelled.mode = NavMode::kVerticalGyro;
  levelled.header.valid = NavSolution::kValidAttitude | NavSolution::kValidAttitudeStd;
  {
    CsvPoseWriter w((dir / "p.csv").string());
    OutputEpoch e{.solution = s};
    w.write(e);  // not a pose epoch: no row
    e.pose_due = true;
    w.write(e);
    e.solution = levelled;
    w.write(e);
    w.commit();
  }
  const std::string text = read_text(dir / "p.csv");
  const std::string rows = text.substr(text.find('\n') + 1);
  // Not levelled (no kValidBiases): the 38 calibration columns appended at the end are nan.
  std::string no_calibration;
  for (int i = 0; i < 38; ++i) no_calibration += ",nan";
  EXPECT_EQ(rows,
            "1234567890.000000005,gps,navigation,45.0000000000,-120.5000000000,100.2500,1.00000,-2.00000,"
            "0.50000,1.000000,-2.000000,90.000000,0.5000,0.5000,1.0000,0.01000,0.02000,0.03000,0.100000,"
            "0.100000,0.500000" + no_calibration + "\n"
            "1234567890.000000005,gps,vertical_gyro,nan,nan,nan,nan,nan,nan,1.000000,-2.000000,nan,nan,nan,nan,"
            "nan,nan,nan,0.100000,0.100000,0.500000" + no_calibration + "\n");
}

TEST(CsvPoseWriter, CalibrationColumnsAppendedAfterThePoseColumns) {
  const auto dir = scratch_dir();
  NavSolution s;
  s.header.valid = NavSolution::kValidBiases;
  // 1e-5 rad/s = 1e-5 * 180 / pi * 3600 deg/h = 2.0626 deg/h; 2e-5 rad/s std = 4.1253 deg/h.
  s.gyro_bias_rps = {1e-5, -1e-5, 0.0};
  s.gyro_bias_std_rps = {2e-5, 2e-5, 2e-5};
  s.accel_bias_mps2 = {0.01, 0.0, -0.02};
  s.accel_bias_std_mps2 = {0.001, 0.001, 0.002};
  s.calibration.odometer_scale_error = {.estimated = true, .value = 0.0125, .std = 0.002};
  s.calibration.gnss_lever_arm_m.estimated = true;
  s.calibration.gnss_lever_arm_m.value = {0.8, -0.4, -1.3};
  s.calibration.gnss_lever_arm_m.std = {0.05, 0.05, 0.1};
  s.calibration.gyro_scale.value = {1e-3, 0, 0};  // not estimated: nan
  // -0.0125 s = -12.50 ms, 0.4 ms std: printed in ms with two decimals.
  s.calibration.gnss_time_offset_s = {.estimated = true, .value = -0.0125, .std = 0.0004};
  {
    CsvPoseWriter w((dir / "c.csv").string());
    w.write(OutputEpoch{.solution = s, .pose_due = true});
    w.commit();
  }
  const std::string text = read_text(dir / "c.csv");
  const std::string header = text.substr(0, text.find('\n'));
  const std::string pose_header =
      "time_s,time_source,mode,lat_deg,lon_deg,height_m,vn_mps,ve_mps,vd_mps,roll_deg,pitch_deg,yaw_deg,"
      "pos_std_n_m,pos_std_e_m,pos_std_d_m,vel_std_n_mps,vel_std_e_mps,vel_std_d_mps,roll_std_deg,"
      "pitch_std_deg,yaw_std_deg,";
  ASSERT_EQ(header.substr(0, pose_header.size()), pose_header);  // the old columns keep their place
  EXPECT_EQ(header.substr(pose_header.size()),
            "gyro_bias_x_deg_h,gyro_bias_y_deg_h,gyro_bias_z_deg_h,gyro_bias_std_x_deg_h,gyro_bias_std_y_deg_h,"
            "gyro_bias_std_z_deg_h,accel_bias_x_mps2,accel_bias_y_mps2,accel_bias_z_mps2,accel_bias_std_x_mps2,"
            "accel_bias_std_y_mps2,accel_bias_std_z_mps2,odometer_scale_error,odometer_scale_error_std,"
            "mount_pitch_deg,mount_yaw_deg,mount_std_pitch_deg,mount_std_yaw_deg,gnss_lever_arm_x_m,"
            "gnss_lever_arm_y_m,gnss_lever_arm_z_m,gnss_lever_arm_std_x_m,gnss_lever_arm_std_y_m,"
            "gnss_lever_arm_std_z_m,gyro_scale_x_ppm,gyro_scale_y_ppm,gyro_scale_z_ppm,gyro_scale_std_x_ppm,"
            "gyro_scale_std_y_ppm,gyro_scale_std_z_ppm,accel_scale_x_ppm,accel_scale_y_ppm,accel_scale_z_ppm,"
            "accel_scale_std_x_ppm,accel_scale_std_y_ppm,accel_scale_std_z_ppm,gnss_time_offset_ms,"
            "gnss_time_offset_std_ms");
  const std::string row = text.substr(text.find('\n') + 1);
  std::string tail = row;
  for (int i = 0; i < 21; ++i) tail = tail.substr(tail.find(',') + 1);  // skip the pose columns
  EXPECT_EQ(tail,
            "2.0626,-2.0626,0.0000,4.1253,4.1253,4.1253,"
            "0.010000,0.000000,-0.020000,0.001000,0.001000,0.002000,"
            "0.012500,0.002000,"
            "nan,nan,nan,nan,"
            "0.8000,-0.4000,-1.3000,0.0500,0.0500,0.1000,"
            "nan,nan,nan,nan,nan,nan,nan,nan,nan,nan,nan,nan,"
            "-12.50,0.40\n");
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

// A solution whose attitude is known, so that IMUOutput can be rebuilt from it.
NavSolution attitude_solution(std::int64_t time_ns) {
  NavSolution s;
  s.header.time_ns = time_ns;
  s.header.time_source = TimeSource::kGps;
  s.header.valid = NavSolution::kValidAttitude | NavSolution::kValidPosition;
  s.gravity_ned_mps2 = {0.0, 0.0, 9.8};
  return s;
}

struct FeFrameSeen {
  std::uint16_t type;
  std::uint32_t sequence;
};

std::vector<FeFrameSeen> fe_frames(const std::vector<std::uint8_t>& bytes) {
  std::vector<FeFrameSeen> seen;
  frontends::fusionengine::Framer framer;
  framer.feed(bytes, [&](const frontends::fusionengine::Frame& f) { seen.push_back({f.header.message_type, f.header.sequence}); });
  EXPECT_EQ(framer.buffered_bytes(), 0u);
  return seen;
}

std::vector<std::uint16_t> types_of(const std::vector<FeFrameSeen>& frames) {
  std::vector<std::uint16_t> types;
  for (const auto& f : frames) types.push_back(f.type);
  return types;
}

constexpr std::uint16_t kPose = 10000, kGnssInfo = 10001, kPoseAux = 10003, kImuOutput = 11000;

TEST(FeEpochEncoder, DefaultRatesAreTheContract) {
  FeEpochEncoder encoder;
  std::vector<std::uint8_t> out;
  // IMU epoch without a pose: IMUOutput only.
  encoder.append(OutputEpoch{.solution = attitude_solution(1'000'000'000)}, out);
  // Pose epoch, no new GNSS: IMUOutput, Pose, PoseAux.
  encoder.append(OutputEpoch{.solution = attitude_solution(1'005'000'000), .pose_due = true, .gnss_fused_total = 0}, out);
  // Pose epoch after a fix was fused: GNSSInfo as well.
  encoder.append(OutputEpoch{.solution = attitude_solution(1'010'000'000), .pose_due = true, .gnss_updated = true,
                             .gnss_fused_total = 1, .num_sats = 9},
                 out);
  const auto frames = fe_frames(out);
  EXPECT_EQ(types_of(frames), (std::vector<std::uint16_t>{kImuOutput, kImuOutput, kPose, kPoseAux, kImuOutput, kPose,
                                                          kPoseAux, kGnssInfo}));
  for (std::size_t i = 0; i < frames.size(); ++i) EXPECT_EQ(frames[i].sequence, i) << "one counter for the stream";
}

TEST(FeEpochEncoder, NoImuOutputBeforeTheAttitudeIsKnown) {
  FeEpochEncoder encoder;
  std::vector<std::uint8_t> out;
  OutputEpoch e{.solution = attitude_solution(1'000'000'000), .pose_due = true};
  e.solution.header.valid = NavSolution::kValidPosition;
  encoder.append(e, out);
  EXPECT_EQ(types_of(fe_frames(out)), (std::vector<std::uint16_t>{kPose, kPoseAux}));
}

TEST(FeEpochEncoder, RatesSetByAClientApply) {
  FeEpochEncoder encoder;
  ASSERT_TRUE(encoder.rates().set(kImuOutput, frontends::fusionengine::MessageRate::kOff));
  ASSERT_TRUE(encoder.rates().set(kPoseAux, frontends::fusionengine::MessageRate::kOff));
  ASSERT_TRUE(encoder.rates().set(kGnssInfo, frontends::fusionengine::MessageRate::kOnChange));
  ASSERT_TRUE(encoder.rates().set(kPose, frontends::fusionengine::MessageRate::k100Ms));
  EXPECT_FALSE(encoder.rates().set(12345, frontends::fusionengine::MessageRate::kOff)) << "not a message navfuse streams";
  std::vector<std::uint8_t> out;
  // 200 Hz epochs over 0.2 s, none a pose epoch by output.rate_hz; one fix fused at 50 ms.
  for (int k = 0; k < 40; ++k) {
    encoder.append(OutputEpoch{.solution = attitude_solution(2'000'000'000LL + k * 5'000'000LL),
                               .gnss_fused_total = k >= 10 ? 1u : 0u},
                   out);
  }
  // Pose on the 100 ms grid (2.0 s, 2.1 s), GNSSInfo once, when the fix count changed.
  EXPECT_EQ(types_of(fe_frames(out)), (std::vector<std::uint16_t>{kPose, kGnssInfo, kPose}));
}

TEST(MipEpochEncoder, FilterPacketsAtPoseEpochsOnly) {
  MipEpochEncoder encoder;
  std::vector<std::uint8_t> out;
  encoder.append(OutputEpoch{.solution = attitude_solution(1'000'000'000)}, out);
  EXPECT_TRUE(out.empty());
  encoder.append(OutputEpoch{.solution = attitude_solution(1'005'000'000), .pose_due = true}, out);
  std::size_t filter_packets = 0;
  frontends::mip::Framer framer;
  framer.feed(out, [&](const frontends::mip::PacketView& p) { filter_packets += p.desc_set == 0x82 ? 1 : 0; });
  EXPECT_GE(filter_packets, 1u);
  EXPECT_EQ(framer.counters().skipped_bytes, 0u);
}

TEST(EncodedFileWriter, FileHoldsExactlyTheEncoderBytes) {
  const auto dir = scratch_dir();
  std::vector<OutputEpoch> epochs;
  for (int k = 0; k < 6; ++k) {
    epochs.push_back(OutputEpoch{.solution = attitude_solution(1'000'000'000LL + k * 5'000'000LL), .pose_due = k % 2 == 0,
                                 .gnss_updated = k == 4, .gnss_fused_total = k >= 4 ? 1u : 0u});
  }
  std::vector<std::uint8_t> expected;
  FeEpochEncoder encoder;
  for (const auto& e : epochs) encoder.append(e, expected);
  {
    FeFileWriter w((dir / "out.p1log").string());
    for (const auto& e : epochs) w.write(e);
    w.commit();
  }
  const std::string text = read_text(dir / "out.p1log");
  EXPECT_EQ(std::vector<std::uint8_t>(text.begin(), text.end()), expected);
}

}  // namespace
}  // namespace navfuse::apps

namespace navfuse::apps {
namespace {

TEST(SummaryCalibration, JsonUsesTheCsvNamesAndTextListsEstimatedGroups) {
  NavSolution s;
  s.header.valid = NavSolution::kValidBiases;
  s.gyro_bias_rps = {1e-5, 0.0, 0.0};
  s.calibration.odometer_scale_error = {.estimated = true, .value = -0.03, .std = 0.004};
  Summary summary;
  for (const CalibrationGroup& g : calibration_groups(s)) {
    if (g.estimated) summary.calibration.push_back(g);
  }
  ASSERT_EQ(summary.calibration.size(), 3u);  // gyro bias, accel bias, odometer scale
  const auto j = summary.to_json(false);
  EXPECT_NEAR(j["calibration"]["gyro_bias_x_deg_h"].get<double>(), 1e-5 * 180.0 / rot::kPi * 3600.0, 1e-12);
  EXPECT_EQ(j["calibration"]["odometer_scale_error"].get<double>(), -0.03);
  EXPECT_EQ(j["calibration"]["odometer_scale_error_std"].get<double>(), 0.004);
  EXPECT_FALSE(j["calibration"].contains("mount_pitch_deg"));
  EXPECT_FALSE(summary.to_json(true).contains("calibration"));
  std::ostringstream text;
  summary.print(text, false);
  EXPECT_NE(text.str().find("calibration at the end (value +- 1 sigma):\n"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("odometer_scale_error        -0.030000 +- 0.004000\n"), std::string::npos) << text.str();
}

}  // namespace
}  // namespace navfuse::apps

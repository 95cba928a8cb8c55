// The status the FusionEngine link reports, checked byte by byte against the spec layouts:
// CalibrationStatus (spec §3.3.5 L1876-1919: stage at 8, yaw/pitch/roll at 12/16/20, their stds
// at 24/28/32, travel at 36, state verified at 64, percents at 68-70 in 0.5 % units, min travel
// at 76, max stds at 80-88; 92 bytes) and SystemStatus (§3.7.1 L2473-2486: temperature at 8,
// 0x7FFF invalid; 128 bytes), with values worked out by hand from a solution whose estimates
// are set by the test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "apps/run/fe_device_status.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/fusionengine/writer.hpp"

namespace navfuse::apps {
namespace {

namespace fe = frontends::fusionengine;

template <class M>
std::vector<std::uint8_t> payload_of(const M& m) {
  std::vector<std::uint8_t> out;
  fe::FusionEngineWriter w;
  w.append(m, out);
  return {out.begin() + fe::kHeaderSize, out.end()};
}
float f32_at(const std::vector<std::uint8_t>& p, std::size_t offset) {
  float v = 0;
  std::memcpy(&v, p.data() + offset, 4);  // little-endian host (x86/arm64)
  return v;
}
std::uint32_t u32_at(const std::vector<std::uint8_t>& p, std::size_t offset) {
  std::uint32_t v = 0;
  std::memcpy(&v, p.data() + offset, 4);
  return v;
}

config::Config estimating_mounting() {
  config::Config c;
  c.imu.estimate_mounting = true;
  c.imu.initial_mounting_std_deg = 1.0;
  c.imu.initial_gyro_bias_std_deg_hr = 20.0;
  c.imu.initial_accel_bias_std_mps2 = 0.01;
  return c;
}

NavSolution navigating_at(std::int64_t time_ns) {
  NavSolution s;
  s.header.time_ns = time_ns;
  s.header.valid = NavSolution::kValidBiases | NavSolution::kValidVelocity;
  s.mode = NavMode::kNavigation;
  s.vel_ned_mps = Eigen::Vector3d(3.0, 4.0, 1.0);  // 5 m/s horizontally
  s.gyro_bias_std_rps = Eigen::Vector3d(1.0, 5.0, 2.0) * rot::kDegToRad / 3600.0;  // worst 5 deg/h
  s.accel_bias_std_mps2 = Eigen::Vector3d(0.001, 0.0025, 0.002);                  // worst 0.0025
  auto& mount = s.calibration.mount_pitch_yaw_rad;
  mount.estimated = true;
  mount.value = Eigen::Vector2d(0.5, -1.0) * rot::kDegToRad;   // pitch, yaw
  mount.std = Eigen::Vector2d(0.5, 0.25) * rot::kDegToRad;
  return s;
}

TEST(FeDeviceStatus, CalibrationStatusBytesWhileEstimatingTheMounting) {
  FeDeviceStatus status(estimating_mounting());
  // 2.5 s at 5 m/s horizontal (the 1 m/s down does not count): 12.5 m travelled.
  for (int k = 0; k <= 25; ++k) status.update(navigating_at(10'000'000'000LL + k * 100'000'000LL));
  const NavSolution s = navigating_at(12'500'000'000LL);
  const auto p = payload_of(status.calibration(s));
  ASSERT_EQ(p.size(), 92u);
  EXPECT_EQ(u32_at(p, 0), 12u);               // P1 time seconds
  EXPECT_EQ(u32_at(p, 4), 500'000'000u);      // and nanoseconds
  EXPECT_EQ(p[8], 0x01);                      // stage: Mounting Angle (L1916)
  EXPECT_FLOAT_EQ(f32_at(p, 12), -1.0f);      // yaw offset, deg
  EXPECT_FLOAT_EQ(f32_at(p, 16), 0.5f);       // pitch offset, deg
  EXPECT_TRUE(std::isnan(f32_at(p, 20)));     // roll: not estimated
  EXPECT_FLOAT_EQ(f32_at(p, 24), 0.25f);      // yaw std
  EXPECT_FLOAT_EQ(f32_at(p, 28), 0.5f);       // pitch std
  EXPECT_TRUE(std::isnan(f32_at(p, 32)));
  EXPECT_NEAR(f32_at(p, 36), 12.5f, 1e-4f);   // travel distance, m
  EXPECT_EQ(p[64], 1);                        // state verified (navigating)
  EXPECT_EQ(p[68], 150);                      // gyro: 1 - 5/20 = 75 % -> 150 half-percent
  EXPECT_EQ(p[69], 150);                      // accel: 1 - 0.0025/0.01 = 75 %
  EXPECT_EQ(p[70], 100);                      // mounting: 1 - 0.5/1 = 50 %
  EXPECT_TRUE(std::isnan(f32_at(p, 76)));     // no minimum travel
  for (std::size_t off : {80u, 84u, 88u}) EXPECT_TRUE(std::isnan(f32_at(p, off))) << off;
  for (std::size_t off = 40; off < 64; ++off) EXPECT_EQ(p[off], 0) << "reserved at " << off;
}

TEST(FeDeviceStatus, CalibrationStatusWithoutMountingEstimationSaysUnknown) {
  FeDeviceStatus status(config::Config{});  // estimate_mounting off
  NavSolution s = navigating_at(1'000'000'000LL);
  s.mode = NavMode::kVerticalGyro;
  status.update(s);
  s.header.time_ns += 1'000'000'000LL;
  status.update(s);
  const auto p = payload_of(status.calibration(s));
  EXPECT_EQ(p[8], 0x00);  // Unknown
  for (std::size_t off : {12u, 16u, 20u, 24u, 28u, 32u}) EXPECT_TRUE(std::isnan(f32_at(p, off))) << off;
  EXPECT_FLOAT_EQ(f32_at(p, 36), 0.0f);  // nothing travelled "for calibration"
  EXPECT_EQ(p[64], 0);                   // not navigating yet
  EXPECT_EQ(p[70], 0);
  s.header.valid = 0;                    // biases not estimated yet: 0 % complete
  const auto q = payload_of(status.calibration(s));
  EXPECT_EQ(q[68], 0);
  EXPECT_EQ(q[69], 0);
}

TEST(FeDeviceStatus, SystemStatusMarksTheTemperaturesInvalid) {
  const auto p = payload_of(FeDeviceStatus::system(navigating_at(7'250'000'000LL)));
  ASSERT_EQ(p.size(), 128u);
  EXPECT_EQ(u32_at(p, 0), 7u);
  EXPECT_EQ(u32_at(p, 4), 250'000'000u);
  EXPECT_EQ(p[8], 0xFF);  // GNSS temperature 0x7FFF little-endian (L2485)
  EXPECT_EQ(p[9], 0x7F);
  EXPECT_EQ(p[10], 0xFF);  // upstream v1 CPU temperature, same invalid value
  EXPECT_EQ(p[11], 0x7F);
}

TEST(FeDeviceStatus, CompletionInHalfPercentUnits) {
  EXPECT_EQ(completion_half_percent(1.0, 1.0), 0);
  EXPECT_EQ(completion_half_percent(0.0, 1.0), 200);
  EXPECT_EQ(completion_half_percent(2.0, 1.0), 0);    // std grew: clamped
  EXPECT_EQ(completion_half_percent(0.1, 1.0), 180);  // 90 %
  EXPECT_EQ(completion_half_percent(0.1, 0.0), 0);    // no prior to compare with
}

}  // namespace
}  // namespace navfuse::apps

// measure_white_noise (calibration/imu_white_noise.hpp): the random-walk densities of white noise
// of known std added to a vehicle-like motion, against sigma * sqrt(dt).
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "calibration/imu_white_noise.hpp"

namespace navfuse::calib {
namespace {

constexpr double kDt = 0.01;  // 100 Hz, as parking_drive's ADIS16465-class IMU

// A car's motion: turns and speed changes on the scale of seconds, gravity on z.
Eigen::Vector3d true_rate_rps(int k) {
  const double t = k * kDt;
  return {0.05 * std::sin(0.7 * t), 0.03 * std::cos(0.5 * t), 0.4 * std::sin(0.25 * t)};
}
Eigen::Vector3d true_force_mps2(int k) {
  const double t = k * kDt;
  return {2.0 * std::sin(0.3 * t), 0.4 * std::sin(0.25 * t) * 5.0, 9.81 + 0.3 * std::cos(0.9 * t)};
}

std::vector<ImuSample> samples(int n, double gyro_std_rps, double accel_std_mps2, bool increments, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<ImuSample> out(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    ImuSample& s = out[static_cast<std::size_t>(k)];
    s.header.time_ns = static_cast<std::int64_t>(k) * 10'000'000;
    s.dt_s = kDt;
    s.quantity = increments ? ImuQuantity::kIncrements : ImuQuantity::kRates;
    const Eigen::Vector3d g = true_rate_rps(k) + gyro_std_rps * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    const Eigen::Vector3d a = true_force_mps2(k) + accel_std_mps2 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    s.gyro = increments ? Eigen::Vector3d(g * kDt) : g;
    s.accel = increments ? Eigen::Vector3d(a * kDt) : a;
  }
  return out;
}

TEST(ImuWhiteNoise, FindsTheDensityOfWhiteNoiseOnAMovingVehicle) {
  // Car vibration at 20 m/s (apps/sim/vibration_model.cpp): 0.5 deg/s and 0.3 m/s^2 per sample.
  const double gyro_std = 0.5 * M_PI / 180.0, accel_std = 0.3;
  for (const bool increments : {false, true}) {
    const auto imu = samples(6000, gyro_std, accel_std, increments, 7);
    const ImuWhiteNoise w = measure_white_noise(imu, 0, imu.size() - 1);
    ASSERT_EQ(w.samples, imu.size() - 2);
    // The median of 18,000 chi-square values: about 1.5 % std on the density.
    EXPECT_NEAR(w.gyro_rad_rts, gyro_std * std::sqrt(kDt), 0.05 * gyro_std * std::sqrt(kDt)) << increments;
    EXPECT_NEAR(w.accel_mps_rts, accel_std * std::sqrt(kDt), 0.05 * accel_std * std::sqrt(kDt)) << increments;
  }
}

TEST(ImuWhiteNoise, BlocksOfIncrementsFindTheSameDensity) {
  const double gyro_std = 0.3 * M_PI / 180.0, accel_std = 0.2;
  const auto imu = samples(12000, gyro_std, accel_std, true, 11);
  // 0.25 s blocks (a 4 Hz receiver's interval): 25 samples each.
  const ImuWhiteNoise w = measure_white_noise(imu, 0, imu.size() - 1, 0.25);
  ASSERT_EQ(w.samples, imu.size() - 3 * 25 + 1);
  // Sliding blocks: ~480 independent ones over 2 minutes, three axes: a few % on the density.
  EXPECT_NEAR(w.gyro_rad_rts, gyro_std * std::sqrt(kDt), 0.1 * gyro_std * std::sqrt(kDt));
  EXPECT_NEAR(w.accel_mps_rts, accel_std * std::sqrt(kDt), 0.1 * accel_std * std::sqrt(kDt));
}

TEST(ImuWhiteNoise, AnEngineToneCountsLittleOverAnIntervalOfIncrements) {
  // Idle vibration (0.1 m/s^2 broadband) with the engine's 26.7 Hz tone of 0.5 m/s^2
  // (apps/sim/vibration_model.cpp) as a raw-increment IMU reports it, (A / w)(cos a - cos b):
  // single samples take the tone for noise four times the broadband (3.95 here), while over
  // 0.25 s it integrates to at most 2 A / w = 6 mm/s, and the blocks find 1.39 times the
  // broadband: what of the tone an IMU factor of that interval still sees.
  const double accel_std = 0.1, amplitude = 0.5, omega = 2.0 * M_PI * 26.7;
  auto imu = samples(12000, 0.0, accel_std, true, 13);
  for (std::size_t k = 0; k < imu.size(); ++k) {
    const double a = omega * static_cast<double>(k) * kDt, b = a + omega * kDt;
    imu[k].accel += amplitude * (std::cos(a) - std::cos(b)) / omega * Eigen::Vector3d(1.0, 1.0, 1.0);
  }
  const double white = accel_std * std::sqrt(kDt);
  EXPECT_GT(measure_white_noise(imu, 0, imu.size() - 1).accel_mps_rts, 3.0 * white);
  EXPECT_LT(measure_white_noise(imu, 0, imu.size() - 1, 0.25).accel_mps_rts, 1.5 * white);
}

TEST(ImuWhiteNoise, TheLeastOfTwoBlockLengthsLeavesAWalkersStepsOut) {
  // A handheld IMU on a walk: steps at 2 Hz of 1.5, 1, 3 m/s^2 on x, y, z, on top of white noise
  // of 0.05 m/s^2. Over 0.25 s blocks (a 4 Hz receiver's interval) the steps look like noise many
  // times the white; between single samples (f'' dt^2 = 3 (4 pi)^2 1e-4 = 0.05 m/s^2 at the peak,
  // against second differences of 0.12 m/s^2 std from the noise) they barely show.
  const double accel_std = 0.05, omega = 2.0 * M_PI * 2.0;
  auto imu = samples(6000, 0.0, accel_std, false, 17);
  for (std::size_t k = 0; k < imu.size(); ++k) {
    const double t = static_cast<double>(k) * kDt;
    imu[k].accel += Eigen::Vector3d(1.5 * std::sin(omega * t + 1.0), std::sin(omega * t + 2.0), 3.0 * std::sin(omega * t));
  }
  const double white = accel_std * std::sqrt(kDt);
  const ImuWhiteNoise single = measure_white_noise(imu, 0, imu.size() - 1);
  const ImuWhiteNoise blocks = measure_white_noise(imu, 0, imu.size() - 1, 0.25);
  EXPECT_GT(blocks.accel_mps_rts, 5.0 * white);
  EXPECT_NEAR(single.accel_mps_rts, white, 0.15 * white);
  const ImuWhiteNoise least = least_white_noise(blocks, single);
  EXPECT_EQ(least.accel_mps_rts, single.accel_mps_rts);
  EXPECT_EQ(least_white_noise(ImuWhiteNoise{}, blocks).accel_mps_rts, blocks.accel_mps_rts);  // nothing measured: ignored
  EXPECT_EQ(least_white_noise(single, ImuWhiteNoise{}).gyro_rad_rts, single.gyro_rad_rts);
}

TEST(ImuWhiteNoise, TheMotionItselfIsNotTakenForNoise) {
  // Without noise the second differences are the motion's (f'' dt^2: 2e-5 m/s^2 per sample for
  // the force's 2 m/s^2 at 0.3 rad/s): below a hundredth of any IMU's data sheet (ADIS16465: ARW
  // 0.15 deg/sqrt(h) = 4.4e-5 rad/sqrt(s), VRW 0.03 m/s/sqrt(h) = 5e-4 m/s/sqrt(s)).
  const auto imu = samples(3000, 0.0, 0.0, false, 1);
  const ImuWhiteNoise w = measure_white_noise(imu, 0, imu.size() - 1);
  ASSERT_GT(w.samples, 0u);
  EXPECT_LT(w.gyro_rad_rts, 1e-2 * 4.4e-5);
  EXPECT_LT(w.accel_mps_rts, 1e-2 * 5e-4);
}

TEST(ImuWhiteNoise, ABumpDoesNotMoveIt) {
  const double gyro_std = 0.1 * M_PI / 180.0, accel_std = 0.1;
  auto imu = samples(200, gyro_std, accel_std, false, 3);
  const ImuWhiteNoise clean = measure_white_noise(imu, 0, imu.size() - 1);
  imu[100].accel.z() += 30.0;  // a pothole: 3 g for one sample
  imu[101].gyro.x() += 1.0;
  const ImuWhiteNoise bumped = measure_white_noise(imu, 0, imu.size() - 1);
  EXPECT_NEAR(bumped.accel_mps_rts, clean.accel_mps_rts, 0.05 * clean.accel_mps_rts);
  EXPECT_NEAR(bumped.gyro_rad_rts, clean.gyro_rad_rts, 0.05 * clean.gyro_rad_rts);
}

TEST(ImuWhiteNoise, TooFewSamplesOrABadRangeMeasureNothing) {
  const auto imu = samples(100, 0.01, 0.1, false, 5);
  EXPECT_EQ(measure_white_noise(imu, 0, kMinWhiteNoiseSamples).samples, 0u);  // 15 differences
  EXPECT_EQ(measure_white_noise(imu, 0, kMinWhiteNoiseSamples + 1).samples, kMinWhiteNoiseSamples);
  EXPECT_EQ(measure_white_noise(imu, 50, 40).samples, 0u);
  EXPECT_EQ(measure_white_noise(imu, 0, imu.size()).samples, 0u);  // past the end
  EXPECT_EQ(measure_white_noise({}, 0, 0).samples, 0u);
}

TEST(ImuWhiteNoise, ANonFiniteSampleIsLeftOut) {
  auto imu = samples(400, 0.01, 0.1, false, 9);
  imu[200].accel.x() = std::nan("");
  imu[210].gyro.y() = INFINITY;
  const ImuWhiteNoise w = measure_white_noise(imu, 0, imu.size() - 1);
  ASSERT_GT(w.samples, 0u);
  EXPECT_TRUE(std::isfinite(w.gyro_rad_rts));
  EXPECT_NEAR(w.accel_mps_rts, 0.1 * std::sqrt(kDt), 0.15 * 0.1 * std::sqrt(kDt));
}

}  // namespace
}  // namespace navfuse::calib

// The bias segments' layout and the weight between neighbours (calibration/bias_segments.hpp),
// against hand-worked numbers.
#include <cmath>

#include <gtest/gtest.h>

#include "calibration/bias_segments.hpp"

namespace navfuse::calib {
namespace {

constexpr std::int64_t kS = 1'000'000'000;

TEST(BiasSegments, EqualSegmentsWithTheRandomWalksStepBetweenThem) {
  // 95 s at 10 s: 10 segments (round(9.5)) of 9.5 s; the step std is q sqrt(9.5).
  const BiasSegments b(5 * kS, 100 * kS, {.length_s = 10.0, .max_count = 120}, 2e-5, 3e-4, Eigen::Vector3d(1, 2, 3),
                       Eigen::Vector3d(4, 5, 6));
  ASSERT_EQ(b.count(), 10u);
  EXPECT_DOUBLE_EQ(b.length_s(), 9.5);
  EXPECT_NEAR(b.gyro_step_std_rps(), 2e-5 * std::sqrt(9.5), 1e-15);
  EXPECT_NEAR(b.accel_step_std_mps2(), 3e-4 * std::sqrt(9.5), 1e-15);
  EXPECT_EQ(b.at(5 * kS), 0u);
  EXPECT_EQ(b.at(5 * kS + 9'499'999'999), 0u);
  EXPECT_EQ(b.at(5 * kS + 9'500'000'000), 1u);
  EXPECT_EQ(b.at(100 * kS), 9u);  // the last stamp belongs to the last segment
  EXPECT_EQ(b.at(0), 0u);         // outside the span: the nearest end
  EXPECT_EQ(b.at(1000 * kS), 9u);
  EXPECT_EQ(b.start_ns(3), 5 * kS + 28'500'000'000);
  for (std::size_t k = 0; k < b.count(); ++k) {
    EXPECT_EQ(b.gyro(k)[2], 3.0);  // every segment starts at the given biases
    EXPECT_EQ(b.accel(k)[0], 4.0);
  }
}

TEST(BiasSegments, OneBiasWhenNothingSaysHowFarNeighboursMayDiffer) {
  const Eigen::Vector3d z = Eigen::Vector3d::Zero();
  EXPECT_EQ(BiasSegments(0, 600 * kS, {.length_s = 10.0}, 0.0, 3e-4, z, z).count(), 1u);  // no gyro drift
  EXPECT_EQ(BiasSegments(0, 600 * kS, {.length_s = 0.0}, 2e-5, 3e-4, z, z).count(), 1u);  // asked for one
  EXPECT_EQ(BiasSegments(0, 4 * kS, {.length_s = 10.0}, 2e-5, 3e-4, z, z).count(), 1u);   // shorter than one
  const BiasSegments one(0, 600 * kS, {.length_s = 0.0}, 2e-5, 3e-4, z, z);
  EXPECT_EQ(one.at(-5 * kS), 0u);
  EXPECT_EQ(one.at(700 * kS), 0u);
  EXPECT_EQ(one.gyro_step_std_rps(), 0.0);
}

TEST(BiasSegments, AnHourGetsAtMostTheCapInLongerSegments) {
  const Eigen::Vector3d z = Eigen::Vector3d::Zero();
  const BiasSegments b(0, 3600 * kS, {.length_s = 10.0, .max_count = 120}, 2e-5, 3e-4, z, z);
  EXPECT_EQ(b.count(), 120u);
  EXPECT_DOUBLE_EQ(b.length_s(), 30.0);
}

TEST(BiasSegments, StepFactorWhitensTheChange) {
  const BiasStepFactor f(0.5);
  const double a[3] = {1.0, 2.0, 3.0}, b[3] = {1.5, 1.0, 3.0};
  double r[3];
  ASSERT_TRUE(f(a, b, r));
  EXPECT_DOUBLE_EQ(r[0], 1.0);
  EXPECT_DOUBLE_EQ(r[1], -2.0);
  EXPECT_DOUBLE_EQ(r[2], 0.0);
}

}  // namespace
}  // namespace navfuse::calib

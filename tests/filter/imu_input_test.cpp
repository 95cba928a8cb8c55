// ImuInput: increments after lost frames span the whole gap, rates are integrated over whatever
// interval passed, and on-time samples are passed through untouched.
#include <gtest/gtest.h>

#include "filter/imu_input.hpp"

namespace navfuse::filter {
namespace {

constexpr std::int64_t kPeriodNs = 5'000'000;  // 200 Hz, VN-300 / MIP demo rate
constexpr double kPeriodS = 0.005;

ImuSample increments(std::int64_t time_ns, const Eigen::Vector3d& rate, const Eigen::Vector3d& force) {
  ImuSample s;
  s.header.time_ns = time_ns;
  s.quantity = ImuQuantity::kIncrements;
  s.frame = SensorFrame::kVehicle;
  s.dt_s = kPeriodS;
  s.gyro = rate * kPeriodS;  // a constant rate: the increment over one period
  s.accel = force * kPeriodS;
  return s;
}

TEST(ImuInput, OnTimeIncrementsPassUnchanged) {
  ImuInput in;
  const Eigen::Vector3d w(0.1, -0.2, 0.3), f(1.0, 2.0, -9.8);
  in.convert(increments(0, w, f));
  const auto out = in.convert(increments(kPeriodNs, w, f));
  ASSERT_TRUE(out);
  EXPECT_EQ(out->dt_s, kPeriodS);
  EXPECT_EQ(out->dtheta_rad, w * kPeriodS);
  EXPECT_EQ(out->dvel_mps, f * kPeriodS);
  // Jitter below the lost-frame threshold (1.4 periods) is not a lost frame.
  const auto late = in.convert(increments(kPeriodNs + 7 * kPeriodNs / 5, w, f));
  ASSERT_TRUE(late);
  EXPECT_EQ(late->dt_s, kPeriodS);
}

TEST(ImuInput, IncrementsAfterLostFramesSpanTheGap) {
  // Constant rates: three frames lost, the fourth's increments stretched over four periods equal
  // the motion over the whole gap exactly (closed form: rate x time).
  ImuInput in;
  const Eigen::Vector3d w(0.1, -0.2, 0.3), f(1.0, 2.0, -9.8);
  in.convert(increments(0, w, f));
  const auto out = in.convert(increments(4 * kPeriodNs, w, f));
  ASSERT_TRUE(out);
  EXPECT_NEAR(out->dt_s, 4 * kPeriodS, 1e-15);
  EXPECT_TRUE(out->dtheta_rad.isApprox(w * 4 * kPeriodS, 1e-12)) << out->dtheta_rad.transpose();
  EXPECT_TRUE(out->dvel_mps.isApprox(f * 4 * kPeriodS, 1e-12)) << out->dvel_mps.transpose();
  // Back on time: one period again.
  const auto next = in.convert(increments(5 * kPeriodNs, w, f));
  ASSERT_TRUE(next);
  EXPECT_EQ(next->dt_s, kPeriodS);
}

TEST(ImuInput, RatesIntegrateOverTheWholeInterval) {
  ImuInput in;
  ImuSample s;
  s.frame = SensorFrame::kVehicle;
  s.dt_s = kPeriodS;
  s.gyro = Eigen::Vector3d(0.0, 0.0, 0.2);
  in.convert(s);
  s.header.time_ns = 3 * kPeriodNs;
  s.gyro = Eigen::Vector3d(0.0, 0.0, 0.4);
  const auto out = in.convert(s);
  ASSERT_TRUE(out);
  EXPECT_NEAR(out->dt_s, 3 * kPeriodS, 1e-15);
  EXPECT_NEAR(out->dtheta_rad.z(), 0.5 * (0.2 + 0.4) * 3 * kPeriodS, 1e-15);  // trapezoid
}

}  // namespace
}  // namespace navfuse::filter

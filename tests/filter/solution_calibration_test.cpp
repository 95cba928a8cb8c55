// The calibration states in the solution: each estimated state's value from the nominal state and
// its std from the covariance diagonal (sqrt of the variance put there by hand); states the
// options do not estimate are marked so.
#include <gtest/gtest.h>

#include "filter/solution.hpp"

namespace navfuse::filter {
namespace {

TEST(SolutionCalibration, ValuesFromTheStateStdsFromTheCovariance) {
  FilterOptions o;
  o.states.wheel_scale = true;
  o.states.gnss_lever_arm = true;
  o.states.mounting = false;
  NavState x;
  x.wheel_scale = 0.015;
  x.gnss_lever_arm_m = {0.8, -0.4, -1.3};
  x.mount_pitch_rad = 0.01;
  x.gyro_scale = {1e-4, 0.0, 0.0};
  Covariance p = Covariance::Zero();
  p(sx::kWheelScale, sx::kWheelScale) = 0.003 * 0.003;
  p(sx::kLeverArm, sx::kLeverArm) = 0.04;      // 0.2 m
  p(sx::kLeverArm + 1, sx::kLeverArm + 1) = 0.01;  // 0.1 m
  p(sx::kLeverArm + 2, sx::kLeverArm + 2) = 0.0;
  StateFieldInputs in;
  capture_state_fields(x, p, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                       Eigen::Matrix3d::Identity(), o.states, in);
  NavSolution out;
  fill_state_fields(in, out);
  const auto& c = out.calibration;
  EXPECT_TRUE(c.odometer_scale_error.estimated);
  EXPECT_EQ(c.odometer_scale_error.value, 0.015);
  EXPECT_DOUBLE_EQ(c.odometer_scale_error.std, 0.003);
  EXPECT_TRUE(c.gnss_lever_arm_m.estimated);
  EXPECT_EQ(c.gnss_lever_arm_m.value, Eigen::Vector3d(0.8, -0.4, -1.3));
  EXPECT_DOUBLE_EQ(c.gnss_lever_arm_m.std.x(), 0.2);
  EXPECT_DOUBLE_EQ(c.gnss_lever_arm_m.std.y(), 0.1);
  EXPECT_EQ(c.gnss_lever_arm_m.std.z(), 0.0);
  EXPECT_FALSE(c.mount_pitch_yaw_rad.estimated);
  EXPECT_EQ(c.mount_pitch_yaw_rad.value.x(), 0.01);
  EXPECT_FALSE(c.gyro_scale.estimated);
  EXPECT_FALSE(c.accel_scale.estimated);
}

}  // namespace
}  // namespace navfuse::filter

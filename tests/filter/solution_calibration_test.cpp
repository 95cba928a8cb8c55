// The calibration states in the solution: each estimated state's value from the nominal state and
// its std from the covariance diagonal (sqrt of the variance put there by hand); states the
// options do not estimate are marked so.
#include <gtest/gtest.h>

#include "core/rotation/rotation.hpp"
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

TEST(SolutionFields, AttitudeStdIsThePhiCovarianceInEulerAngles) {
  // d(roll, pitch, yaw) / d(phi) by central differences of the Euler angles of the attitude
  // turned by a small NED rotation, against the solution's stds of a full attitude covariance,
  // at a pitch where the roll-yaw coupling is large (40 deg) and a level one.
  for (const Eigen::Vector3d& rpy_deg : {Eigen::Vector3d(12.0, 40.0, -130.0), Eigen::Vector3d(-3.0, 2.0, 75.0)}) {
    NavState x;
    x.q_nb = rot::quat_from_rpy(rpy_deg * rot::kDegToRad);
    Eigen::Matrix3d m_fd;
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d d = Eigen::Vector3d::Unit(j) * h;
      const Eigen::Matrix3d c = x.q_nb.toRotationMatrix();
      const Eigen::Vector3d up = rot::rpy_from_dcm(rot::quat_from_rotvec(d).toRotationMatrix() * c);
      const Eigen::Vector3d down = rot::rpy_from_dcm(rot::quat_from_rotvec(-d).toRotationMatrix() * c);
      Eigen::Vector3d diff = up - down;
      diff.z() = rot::wrap_pi(diff.z());
      m_fd.col(j) = diff / (2.0 * h);
    }
    Eigen::Matrix3d a;
    a << 4.0, 1.0, -0.5, 1.0, 2.0, 0.3, -0.5, 0.3, 9.0;
    const Eigen::Matrix3d att_cov = a * 1e-6;  // rad^2, correlated
    Covariance p = Covariance::Zero();
    p.block<3, 3>(sx::kAtt, sx::kAtt) = att_cov;
    StateFieldInputs in;
    capture_state_fields(x, p, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                         Eigen::Matrix3d::Identity(), StateSelection{}, in);
    NavSolution out;
    fill_state_fields(in, out);
    const Eigen::Vector3d expected = (m_fd * att_cov * m_fd.transpose()).diagonal().cwiseSqrt();
    EXPECT_LT((out.att_std_rpy_rad - expected).cwiseAbs().maxCoeff(), 1e-8 * expected.maxCoeff()) << rpy_deg.transpose();
  }
}

}  // namespace
}  // namespace navfuse::filter

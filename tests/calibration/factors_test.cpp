// The calibration's residuals (autodiff functors) on cases worked by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "calibration/gnss_factors.hpp"
#include "calibration/mounting_rotation.hpp"
#include "calibration/odometry_factors.hpp"
#include "calibration/preintegration_factor.hpp"
#include "calibration/vehicle_velocity_factor.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::calib {
namespace {

constexpr double kDeg = rot::kDegToRad;

// Eigen order x y z w of a yaw rotation about z (tangent NED <- sensor).
std::array<double, 4> yaw_quat(double yaw_rad) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
  return {q.x(), q.y(), q.z(), q.w()};
}

TEST(CalibrationFactors, MountingRotationIsCoreDcm) {
  const Eigen::Vector3d rpy(0.3 * kDeg, -1.5 * kDeg, 170.0 * kDeg);
  EXPECT_TRUE(dcm_from_rpy(rpy.x(), rpy.y(), rpy.z()).isApprox(rot::dcm_from_rpy(rpy), 1e-15));
}

TEST(CalibrationFactors, GnssPositionThroughLeverArmAndClockOffset) {
  // Sensor x pointing east (yaw 90 deg) while moving north at 10 m/s: p (1, 2, 3), turning at
  // 0.5 rad/s; antenna 1 m forward. R l = (0, 1, 0); omega x l = (0, 0.5, 0) in the body, (-0.5, 0,
  // 0) in NED; the antenna moves at (9.5, 0, 0) for tau - dt = 0.1 - 0.05 s: (1.475, 3, 3).
  EpochKnowns k;
  k.rate_s_rps = Eigen::Vector3d(0.0, 0.0, 0.5);
  const GnssPositionFactor f(Eigen::Vector3d(1.4, 3.1, 3.0), Eigen::Matrix3d::Identity(), 0.1, k);
  const double p[3] = {1, 2, 3}, v[3] = {10, 0, 0}, lever[3] = {1, 0, 0}, mount[2] = {0, 0}, dt[1] = {0.05};
  const auto q = yaw_quat(90.0 * kDeg);
  double r[3];
  ASSERT_TRUE(f(p, v, q.data(), lever, mount, dt, r));
  EXPECT_NEAR(r[0], 0.075, 1e-12);
  EXPECT_NEAR(r[1], -0.1, 1e-12);
  EXPECT_NEAR(r[2], 0.0, 1e-12);
  // Whitening: a covariance of 4 m^2 halves every component.
  const GnssPositionFactor g(Eigen::Vector3d(1.4, 3.1, 3.0), 4.0 * Eigen::Matrix3d::Identity(), 0.1, k);
  ASSERT_TRUE(g(p, v, q.data(), lever, mount, dt, r));
  EXPECT_NEAR(r[0], 0.0375, 1e-12);
}

TEST(CalibrationFactors, ExternalAxesWeighOnlyWhatIsValid) {
  // The case above (raw residual 0.075, -0.1, 0) with per-axis std devs (2, 4, 1) and the
  // second axis invalid: (0.0375, 0, 0). In axes that swap north and east, both valid with std 1:
  // (-0.1, 0.075, 0), the third axis invalid.
  EpochKnowns k;
  k.rate_s_rps = Eigen::Vector3d(0.0, 0.0, 0.5);
  const double p[3] = {1, 2, 3}, v[3] = {10, 0, 0}, lever[3] = {1, 0, 0}, mount[2] = {0, 0}, dt[1] = {0.05};
  const auto q = yaw_quat(90.0 * kDeg);
  double r[3];
  const GnssPositionFactor f(Eigen::Vector3d(1.4, 3.1, 3.0),
                             axis_sqrt_information(Eigen::Vector3d(2, 4, 1), 0b101u, Eigen::Matrix3d::Identity()), 0.1, k);
  ASSERT_TRUE(f(p, v, q.data(), lever, mount, dt, r));
  EXPECT_NEAR(r[0], 0.0375, 1e-12);
  EXPECT_EQ(r[1], 0.0);
  EXPECT_NEAR(r[2], 0.0, 1e-12);
  Eigen::Matrix3d swap;
  swap << 0, 1, 0, 1, 0, 0, 0, 0, 1;
  const GnssPositionFactor g(Eigen::Vector3d(1.4, 3.1, 3.0),
                             axis_sqrt_information(Eigen::Vector3d::Ones(), 0b011u, swap), 0.1, k);
  ASSERT_TRUE(g(p, v, q.data(), lever, mount, dt, r));
  EXPECT_NEAR(r[0], -0.1, 1e-12);
  EXPECT_NEAR(r[1], 0.075, 1e-12);
  EXPECT_EQ(r[2], 0.0);
}

TEST(CalibrationFactors, GnssVelocityMovesWithAcceleration) {
  // Still vehicle accelerating north at 2 m/s^2; the fix is 0.05 s later than the state on the
  // IMU clock (tau 0.1, offset 0.05): predicted (0.1, 0, 0).
  EpochKnowns k;
  k.accel_t_mps2 = Eigen::Vector3d(2.0, 0.0, 0.0);
  const GnssVelocityFactor f(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), 0.1, k);
  const double v[3] = {0, 0, 0}, lever[3] = {0, 0, 0}, mount[2] = {0, 0}, dt[1] = {0.05};
  const auto q = yaw_quat(0.0);
  double r[3];
  ASSERT_TRUE(f(v, q.data(), lever, mount, dt, r));
  EXPECT_NEAR(r[0], 0.1, 1e-12);
  EXPECT_NEAR(r[1], 0.0, 1e-12);
}

TEST(CalibrationFactors, GnssHeadingSeesTheMountingYawAndTheBaselinesTurn) {
  // Sensor x pointing east (yaw 90 deg), baseline along the vehicle's x, the tangent frame's
  // north the local one. Mounting yaw residual 1 deg: C_nv = C_ns C_vs^T = R_z(90 - 1), so the
  // baseline points at 89 deg. A receiver saying 89.5 deg with a 0.25 deg std: residual -2.
  EpochKnowns k;
  const Eigen::Vector3d baseline_v = Eigen::Vector3d::UnitX();
  const auto q = yaw_quat(90.0 * kDeg);
  const double mount[2] = {0.0, 1.0 * kDeg}, dt[1] = {0.0};
  double r[1];
  const GnssHeadingFactor f(89.5 * kDeg, 0.25 * kDeg, baseline_v, Eigen::Matrix3d::Identity(), 0.0, k);
  ASSERT_TRUE(f(q.data(), mount, dt, r));
  EXPECT_NEAR(r[0], -2.0, 1e-9);
  // Across +-180 deg: a baseline at 179.5 deg against a measured -179.5 deg is 1 deg short.
  const auto q_south = yaw_quat(179.5 * kDeg);
  const double level[2] = {0.0, 0.0};
  const GnssHeadingFactor wrap(-179.5 * kDeg, 1.0 * kDeg, baseline_v, Eigen::Matrix3d::Identity(), 0.0, k);
  ASSERT_TRUE(wrap(q_south.data(), level, dt, r));
  EXPECT_NEAR(r[0], -1.0, 1e-9);
  // Turning at 0.5 rad/s about down, the fix 0.05 s after the state less a 0.03 s clock offset:
  // the baseline (1, 0, 0) in the sensor moves to (1, 0.01, 0), azimuth 90 + atan(0.01).
  k.rate_s_rps = Eigen::Vector3d(0.0, 0.0, 0.5);
  const double offset[1] = {0.03};
  const GnssHeadingFactor turning(90.0 * kDeg, 1.0 * kDeg, baseline_v, Eigen::Matrix3d::Identity(), 0.05, k);
  ASSERT_TRUE(turning(q.data(), level, offset, r));
  EXPECT_NEAR(r[0], std::atan(0.01) / kDeg, 1e-9);
  // The tangent frame turned from the local NED (meridian convergence): C_nt adds its angle.
  const Eigen::Matrix3d c_nt = Eigen::AngleAxisd(0.2 * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const GnssHeadingFactor converged(90.0 * kDeg, 1.0 * kDeg, baseline_v, c_nt, 0.0, EpochKnowns{});
  ASSERT_TRUE(converged(q.data(), level, dt, r));
  EXPECT_NEAR(r[0], 0.2, 1e-9);
}

TEST(CalibrationFactors, WheelSpeedAndNhcSeeTheMounting) {
  // Driving east at 10 m/s, sensor x along the motion (yaw 90 deg); the IMU turned 1 deg in yaw
  // from the vehicle: the vehicle sees (10 cos 1, 10 sin 1, 0) m/s.
  const double v[3] = {0, 10, 0}, mount[2] = {0, 1.0 * kDeg}, scale[1] = {1.01}, dt[1] = {0.0};
  const auto q = yaw_quat(90.0 * kDeg);
  const NhcFactor nhc(0.1, 0.2, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  const double at_imu[3] = {0, 0, 0};
  double r[2];
  ASSERT_TRUE(nhc(v, q.data(), mount, at_imu, r));
  EXPECT_NEAR(r[0], 10.0 * std::sin(1.0 * kDeg) / 0.1, 1e-9);
  EXPECT_NEAR(r[1], 0.0, 1e-9);
  // Odometer reading 10.2 with its slope 1 m/s^2 over an offset change of 0.01 s: 10.21 measured
  // against 1.01 * 10 cos 1 deg.
  const WheelSpeedFactor wheel(10.2, 1.0, -0.01, 0.05, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(),
                               Eigen::Vector3d::Zero());
  double w[1];
  ASSERT_TRUE(wheel(v, q.data(), mount, scale, dt, w));
  EXPECT_NEAR(w[0], (10.21 - 1.01 * 10.0 * std::cos(1.0 * kDeg)) / 0.05, 1e-9);
  // A lever arm behind the IMU while turning right at 0.5 rad/s: the point 1.2 m back slides left
  // at 0.6 m/s (omega x l = (0, 0, 0.5) x (-1.2, 0, 0) = (0, -0.6, 0)).
  const double straight[2] = {0, 0};
  const NhcFactor rear(1.0, 1.0, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 0.5));
  const double axle[3] = {-1.2, 0, 0};
  ASSERT_TRUE(rear(v, q.data(), straight, axle, r));
  EXPECT_NEAR(r[0], -0.6, 1e-9);
}

TEST(CalibrationFactors, VehicleFrameVelocityTurnsWithTheVehicle) {
  // Driving east at 10 m/s, sensor axes the vehicle's (yaw 90 deg), turning right at 0.5 rad/s:
  // the velocity swings south at a = (-5, 0, 0) m/s^2. Over tau - dt = 0.1 - 0.05 s the tangent
  // velocity becomes (-0.25, 10, 0), (10, 0.25, 0) in the epoch's sensor axes, and the axes turn
  // by omega x v d = (0, 0.25, 0): (10, 0, 0), no sideways velocity. The aiding sits 1.2 m behind
  // the IMU and slides left at omega x l = (0, -0.6, 0). Measured (10.1, -0.5, 0.3) with std
  // (0.1, 0.2, 1) and z invalid: residual (-1, -0.5, 0).
  EpochKnowns k;
  k.rate_s_rps = Eigen::Vector3d(0.0, 0.0, 0.5);
  k.accel_t_mps2 = Eigen::Vector3d(-5.0, 0.0, 0.0);
  const double v[3] = {0, 10, 0}, level[2] = {0, 0}, dt[1] = {0.05};
  const auto q = yaw_quat(90.0 * kDeg);
  const VehicleVelocityFactor f(Eigen::Vector3d(10.1, -0.5, 0.3),
                                axis_sqrt_information(Eigen::Vector3d(0.1, 0.2, 1.0), 0b011u, Eigen::Matrix3d::Identity()),
                                Eigen::Vector3d(-1.2, 0.0, 0.0), 0.1, k);
  double r[3];
  ASSERT_TRUE(f(v, q.data(), level, dt, r));
  EXPECT_NEAR(r[0], -1.0, 1e-9);
  EXPECT_NEAR(r[1], -0.5, 1e-9);
  EXPECT_EQ(r[2], 0.0);
  // Not turning, the IMU 1 deg in yaw from the vehicle (residual yaw): the vehicle sees
  // (10 cos 1, 10 sin 1, 0) m/s against a measured (10, 0, 0) with unit std.
  const double yawed[2] = {0.0, 1.0 * kDeg}, now[1] = {0.0};
  const VehicleVelocityFactor g(Eigen::Vector3d(10.0, 0.0, 0.0),
                                axis_sqrt_information(Eigen::Vector3d::Ones(), 0b111u, Eigen::Matrix3d::Identity()),
                                Eigen::Vector3d::Zero(), 0.0, EpochKnowns{});
  ASSERT_TRUE(g(v, q.data(), yawed, now, r));
  EXPECT_NEAR(r[0], 10.0 * std::cos(1.0 * kDeg) - 10.0, 1e-9);
  EXPECT_NEAR(r[1], 10.0 * std::sin(1.0 * kDeg), 1e-9);
  EXPECT_NEAR(r[2], 0.0, 1e-9);
}

TEST(CalibrationFactors, TheMountingResidualIsAboutTheVehicleAxesWhateverTheSensorsOrientation) {
  // A sensor mounted x right, z up (roll 180, yaw -90) on a level car driving north at 10 m/s:
  // C_ts = C_vs0^T. The residual pitch turns the vehicle frame about its own y axis, so the car
  // is seen climbing: v_v = R_y(dp) (10, 0, 0) = (10 cos dp, 0, -10 sin dp), and NHC's vertical
  // residual is -10 sin dp / std. (Taken as the config key's Euler pitch instead, the same angle
  // would turn the vehicle frame about its x axis, a roll, and the NHC would see nothing.)
  const Eigen::Matrix3d c_vs0 = rot::dcm_from_rpy(Eigen::Vector3d(180.0 * kDeg, 0.0, -90.0 * kDeg));
  const Eigen::Quaterniond q_ts(c_vs0.transpose());
  const double q[4] = {q_ts.x(), q_ts.y(), q_ts.z(), q_ts.w()};
  const double v[3] = {10, 0, 0}, pitched[2] = {2.0 * kDeg, 0.0}, yawed[2] = {0.0, 2.0 * kDeg};
  const NhcFactor nhc(0.1, 0.2, c_vs0, Eigen::Vector3d::Zero());
  const double at_imu[3] = {0, 0, 0};
  double r[2];
  ASSERT_TRUE(nhc(v, q, pitched, at_imu, r));
  EXPECT_NEAR(r[0], 0.0, 1e-9);
  EXPECT_NEAR(r[1], -10.0 * std::sin(2.0 * kDeg) / 0.2, 1e-9);
  // The residual yaw: v_v = R_z(dy) (10, 0, 0) = (10 cos dy, 10 sin dy, 0).
  ASSERT_TRUE(nhc(v, q, yawed, at_imu, r));
  EXPECT_NEAR(r[0], 10.0 * std::sin(2.0 * kDeg) / 0.1, 1e-9);
  EXPECT_NEAR(r[1], 0.0, 1e-9);
  // With a sensor mounted in the vehicle axes but for a roll, the residuals are the config key's
  // own Euler pitch and yaw (C_vs0 = R_x(roll)).
  const Eigen::Vector3d rpy(0.3 * kDeg, 1.5 * kDeg, -2.0 * kDeg);
  const double residual[2] = {rpy.y(), rpy.z()};
  EXPECT_TRUE(mounting_dcm(residual, rot::dcm_from_rpy(Eigen::Vector3d(rpy.x(), 0.0, 0.0)))
                  .isApprox(rot::dcm_from_rpy(rpy), 1e-15));
}

TEST(CalibrationFactors, PreintegrationZeroWhenConsistentAndSeesABiasChange) {
  // At rest, level, 1 s: the accelerometer reads -g, so dv = (0, 0, -9.8), dp = (0, 0, -4.9),
  // and the states (still) agree exactly.
  const Eigen::Vector3d g(0.0, 0.0, 9.8);
  ImuPreintegration pre(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(),
                        Eigen::Vector3d::Zero(), {.gyro_rad_rts = 1e-3, .accel_mps_rts = 1e-2});
  for (int k = 0; k < 100; ++k) pre.add(Eigen::Vector3d::Zero(), -g * 0.01, 0.01);
  const PreintegrationFactor f(pre, g, Eigen::Vector3d::Zero());
  const double p[3] = {0, 0, 0}, v[3] = {0, 0, 0}, zero[3] = {0, 0, 0};
  const auto q = yaw_quat(0.0);
  double r[9];
  ASSERT_TRUE(f(p, v, q.data(), p, v, q.data(), zero, zero, zero, zero, r));
  for (double x : r) EXPECT_NEAR(x, 0.0, 1e-9);
  // An accelerometer bias of 0.01 m/s^2 on x: the true increments are 0.01 m/s and 0.005 m
  // smaller on x than measured, so the residuals are +0.01 and +0.005 before whitening.
  const double ba[3] = {0.01, 0, 0};
  ASSERT_TRUE(f(p, v, q.data(), p, v, q.data(), zero, ba, zero, zero, r));
  Eigen::Matrix<double, 9, 1> expected = Eigen::Matrix<double, 9, 1>::Zero();
  expected[3] = 0.01;
  expected[6] = 0.005;
  const Eigen::Matrix<double, 9, 9> info = pre.covariance().inverse();
  const Eigen::Matrix<double, 9, 1> whitened = Eigen::LLT<Eigen::Matrix<double, 9, 9>>(info).matrixU() * expected;
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(r[i], whitened[i], 1e-6 * whitened.norm()) << i;
}

}  // namespace
}  // namespace navfuse::calib

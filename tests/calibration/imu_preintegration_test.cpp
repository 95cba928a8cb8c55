// ImuPreintegration (calibration/imu_preintegration.hpp): the increments against closed forms,
// and its analytic error-parameter Jacobians against central differences of re-integration.
#include <cmath>

#include <gtest/gtest.h>

#include "calibration/imu_preintegration.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::calib {
namespace {

constexpr double kDt = 0.005;
constexpr int kSamples = 200;  // 1 s

const ImuNoiseDensity kNoise{.gyro_rad_rts = 1e-4, .accel_mps_rts = 1e-3};

// A sample sequence with turning and changing force: rate and force vary per sample.
Eigen::Vector3d rate(int k) { return {0.3 * std::sin(0.05 * k), -0.2, 0.5 + 0.1 * std::cos(0.03 * k)}; }
Eigen::Vector3d force(int k) { return {1.0 + 0.5 * std::sin(0.04 * k), -0.3, -9.8 + 0.2 * std::cos(0.07 * k)}; }

// Integrates the sequence with the IMU error parameters x = [bg, ba, sg, sa] applied to the
// measurements (measured = (1 + s) true + b), about bg0 = ba0 = 0 and no earth rate.
ImuPreintegration integrate(const Eigen::Matrix<double, 12, 1>& x) {
  ImuPreintegration p(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(),
                      Eigen::Vector3d::Zero(), kNoise);
  for (int k = 0; k < kSamples; ++k) {
    const Eigen::Vector3d theta = rate(k) * kDt, vel = force(k) * kDt;
    // The measurements a sensor with errors x gives for the true increments theta, vel, fed to a
    // preintegration that assumes none: its Jacobian maps x to the increments' change.
    const Eigen::Vector3d m_theta = (Eigen::Vector3d::Ones() + x.segment<3>(kGyroScale)).cwiseProduct(theta) + x.segment<3>(kGyroBias) * kDt;
    const Eigen::Vector3d m_vel = (Eigen::Vector3d::Ones() + x.segment<3>(kAccelScale)).cwiseProduct(vel) + x.segment<3>(kAccelBias) * kDt;
    p.add(m_theta, m_vel, kDt);
  }
  return p;
}

TEST(ImuPreintegration, ConstantRateAndForceMatchClosedForm) {
  // Rotation at constant rate w about z and a force constant in the body: the increments are
  // dR = Exp(w T), dv = int_0^T Exp(w t) f dt, dp = int_0^T int_0^t Exp(w s) f ds dt.
  const double w = 0.4, t_end = 1.0;
  const Eigen::Vector3d f(2.0, 0.0, -9.8);
  ImuPreintegration p(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(),
                      Eigen::Vector3d::Zero(), kNoise);
  const int n = 2000;
  const double dt = t_end / n;
  for (int k = 0; k < n; ++k) {
    // Increments as a coning/sculling-compensating IMU reports them: exact rotation, and the
    // force integrated in the body frame at the sample's start.
    const double s = std::sin(w * dt), c = std::cos(w * dt);
    const Eigen::Vector3d dvel((f.x() * s - f.y() * (1.0 - c)) / w, (f.x() * (1.0 - c) + f.y() * s) / w, f.z() * dt);
    p.add(Eigen::Vector3d(0.0, 0.0, w * dt), dvel, dt);
  }
  const double s = std::sin(w * t_end), c = std::cos(w * t_end);
  const Eigen::Vector3d dv((f.x() * s - f.y() * (1.0 - c)) / w, (f.x() * (1.0 - c) + f.y() * s) / w, f.z() * t_end);
  const Eigen::Vector3d dp((f.x() * (1.0 - c) / (w * w)), (f.x() * (w * t_end - s) / (w * w)), 0.5 * f.z() * t_end * t_end);
  EXPECT_NEAR(p.dt(), t_end, 1e-12);
  EXPECT_TRUE(p.delta_r().isApprox(rot::quat_from_rotvec(Eigen::Vector3d(0, 0, w * t_end)).toRotationMatrix(), 1e-12));
  EXPECT_LT((p.delta_v() - dv).norm(), 1e-9);
  EXPECT_LT((p.delta_p() - dp).norm(), 1e-6);  // the per-sample step is exact to O(dt^2) in position
}

TEST(ImuPreintegration, ErrorJacobiansMatchCentralDifferences) {
  const ImuPreintegration base = integrate(Eigen::Matrix<double, 12, 1>::Zero());
  const Eigen::Matrix<double, 9, 12>& j = base.jacobian();
  const double steps[4] = {1e-5, 1e-4, 1e-5, 1e-5};  // bg rad/s, ba m/s^2, sg, sa
  for (int col = 0; col < 12; ++col) {
    Eigen::Matrix<double, 12, 1> x = Eigen::Matrix<double, 12, 1>::Zero();
    const double h = steps[col / 3];
    x[col] = h;
    const ImuPreintegration plus = integrate(x);
    x[col] = -h;
    const ImuPreintegration minus = integrate(x);
    // The rotation's change as a right perturbation: Log(dR^T dR(x)).
    const Eigen::Vector3d d_rot = (rot::rotvec_from_quat(Eigen::Quaterniond(base.delta_r().transpose() * plus.delta_r())) -
                                   rot::rotvec_from_quat(Eigen::Quaterniond(base.delta_r().transpose() * minus.delta_r()))) /
                                  (2.0 * h);
    const Eigen::Vector3d d_vel = (plus.delta_v() - minus.delta_v()) / (2.0 * h);
    const Eigen::Vector3d d_pos = (plus.delta_p() - minus.delta_p()) / (2.0 * h);
    // The measurements move by the error; the preintegration's Jacobian is of the increments
    // with respect to a parameter removed from them: the opposite sign.
    const double tol_r = 1e-4 * (1.0 + j.col(col).head<3>().norm());
    const double tol = 1e-4 * (1.0 + j.col(col).tail<6>().norm());
    EXPECT_LT((d_rot + j.col(col).head<3>()).norm(), tol_r) << "column " << col;
    EXPECT_LT((d_vel + j.col(col).segment<3>(3)).norm(), tol) << "column " << col;
    EXPECT_LT((d_pos + j.col(col).tail<3>()).norm(), tol) << "column " << col;
  }
}

TEST(ImuPreintegration, CovarianceGrowsLikeARandomWalk) {
  // No motion: the angle variance is ARW^2 T, the velocity variance VRW^2 T (Forster eq. 63 with
  // dR = I).
  ImuPreintegration p(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(),
                      Eigen::Vector3d::Zero(), kNoise);
  for (int k = 0; k < kSamples; ++k) p.add(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), kDt);
  const double t = kSamples * kDt;
  EXPECT_NEAR(p.covariance()(0, 0), kNoise.gyro_rad_rts * kNoise.gyro_rad_rts * t, 1e-15);
  EXPECT_NEAR(p.covariance()(3, 3), kNoise.accel_mps_rts * kNoise.accel_mps_rts * t, 1e-15);
  // Position: the integral of a velocity random walk, VRW^2 T^3 / 3 (to the discretisation).
  EXPECT_NEAR(p.covariance()(6, 6), kNoise.accel_mps_rts * kNoise.accel_mps_rts * t * t * t / 3.0, 1e-3 * 1e-6 * t);
}

}  // namespace
}  // namespace navfuse::calib

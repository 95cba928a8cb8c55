#include "calibration/imu_preintegration.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"

namespace navfuse::calib {

Eigen::Matrix3d right_jacobian(const Eigen::Vector3d& phi) {
  const double a = phi.norm();
  const Eigen::Matrix3d k = rot::skew(phi);
  if (a < 1e-6) return Eigen::Matrix3d::Identity() - 0.5 * k;
  return Eigen::Matrix3d::Identity() - (1.0 - std::cos(a)) / (a * a) * k + (a - std::sin(a)) / (a * a * a) * k * k;
}

ImuPreintegration::ImuPreintegration(const Eigen::Vector3d& bg0, const Eigen::Vector3d& ba0,
                                     const Eigen::Matrix3d& c_tb_i, const Eigen::Vector3d& earth_rate_t,
                                     const ImuNoiseDensity& noise)
    : bg0_(bg0), ba0_(ba0), c_bt_i_(c_tb_i.transpose()), earth_rate_t_(earth_rate_t), noise_(noise) {}

void ImuPreintegration::add(const Eigen::Vector3d& dtheta_rad, const Eigen::Vector3d& dvel_mps, double dt_s) {
  // Earth rate seen in the body at this sample: C_b(k)t = dR^T C_b(i)t.
  const Eigen::Vector3d earth_b = dr_.transpose() * (c_bt_i_ * earth_rate_t_);
  const Eigen::Vector3d dtheta = dtheta_rad - (bg0_ + earth_b) * dt_s;
  const Eigen::Vector3d dvel = dvel_mps - ba0_ * dt_s;
  const Eigen::Matrix3d step = rot::quat_from_rotvec(dtheta).toRotationMatrix();
  const Eigen::Matrix3d jr = right_jacobian(dtheta);
  const Eigen::Matrix3d dr_dvel_x = dr_ * rot::skew(dvel);

  // Covariance first (it uses the increments before this sample), Forster eq. 62-63: the error
  // state is [dphi, dv, dp]; the noise enters through the angle and velocity increments.
  Eigen::Matrix<double, 9, 9> a = Eigen::Matrix<double, 9, 9>::Identity();
  a.block<3, 3>(0, 0) = step.transpose();
  a.block<3, 3>(3, 0) = -dr_dvel_x;
  a.block<3, 3>(6, 0) = -0.5 * dr_dvel_x * dt_s;
  a.block<3, 3>(6, 3) = Eigen::Matrix3d::Identity() * dt_s;
  Eigen::Matrix<double, 9, 6> b = Eigen::Matrix<double, 9, 6>::Zero();
  b.block<3, 3>(0, 0) = jr;
  b.block<3, 3>(3, 3) = dr_;
  b.block<3, 3>(6, 3) = 0.5 * dr_ * dt_s;
  Eigen::Matrix<double, 6, 6> q = Eigen::Matrix<double, 6, 6>::Zero();
  q.diagonal() << Eigen::Vector3d::Constant(noise_.gyro_rad_rts * noise_.gyro_rad_rts * dt_s),
      Eigen::Vector3d::Constant(noise_.accel_mps_rts * noise_.accel_mps_rts * dt_s);
  cov_ = a * cov_ * a.transpose() + b * q * b.transpose();

  // Error-parameter Jacobians (Forster appendix B, eqs. 69-70, for any parameter x whose effect
  // on this sample's increments is G = d(dtheta)/dx, A = d(dvel)/dx):
  //   dp/dx += dv/dx dt + dR (A - [dvel]x dR/dx) dt / 2,  dv/dx += dR (A - [dvel]x dR/dx),
  //   dR/dx  = step^T dR/dx + J_r G.
  // Biases: G = -dt I (gyro), A = -dt I (accel); scale factors: G = -diag(dtheta_meas),
  // A = -diag(dvel_meas).
  Eigen::Matrix<double, 3, 12> g = Eigen::Matrix<double, 3, 12>::Zero(), acc = Eigen::Matrix<double, 3, 12>::Zero();
  g.block<3, 3>(0, kGyroBias) = -dt_s * Eigen::Matrix3d::Identity();
  acc.block<3, 3>(0, kAccelBias) = -dt_s * Eigen::Matrix3d::Identity();
  g.block<3, 3>(0, kGyroScale) = -Eigen::Matrix3d(dtheta_rad.asDiagonal());
  acc.block<3, 3>(0, kAccelScale) = -Eigen::Matrix3d(dvel_mps.asDiagonal());
  const Eigen::Matrix<double, 3, 12> dvel_dx = acc - rot::skew(dvel) * jac_.topRows<3>();
  jac_.bottomRows<3>() += jac_.middleRows<3>(3) * dt_s + 0.5 * dr_ * dvel_dx * dt_s;
  jac_.middleRows<3>(3) += dr_ * dvel_dx;
  jac_.topRows<3>() = step.transpose() * jac_.topRows<3>() + jr * g;

  // Increments (Forster eq. 33-35, one sample): position and velocity with the rotation so far.
  dp_ += dv_ * dt_s + 0.5 * dr_ * dvel * dt_s;
  dv_ += dr_ * dvel;
  dr_ = dr_ * step;
  dt_ += dt_s;
}

void ImuPreintegration::add_bias_drift(double gyro_rps_rts, double accel_mps2_rts) {
  // A bias random walk over T integrates to an angle (velocity) error of variance q T^3 / 3 and a
  // position error of q T^5 / 20 (Groves 2nd ed. §14.2.7 for the integrals of a random walk).
  const double t = dt_;
  const double g2 = gyro_rps_rts * gyro_rps_rts, a2 = accel_mps2_rts * accel_mps2_rts;
  cov_.block<3, 3>(0, 0).diagonal().array() += g2 * t * t * t / 3.0;
  cov_.block<3, 3>(3, 3).diagonal().array() += a2 * t * t * t / 3.0;
  cov_.block<3, 3>(6, 6).diagonal().array() += a2 * t * t * t * t * t / 20.0;
}

}  // namespace navfuse::calib

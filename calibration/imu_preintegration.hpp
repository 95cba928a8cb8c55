// IMU preintegration between two states (Forster, Carlone, Dellaert & Scaramuzza, "On-Manifold
// Preintegration for Real-Time Visual-Inertial Odometry", IEEE T-RO 33(1), 2017): the rotation,
// velocity and position increments of the IMU samples between epochs i and j in the body frame
// of i (eqs. 33-35, discrete form), their first-order Jacobians with respect to the gyro and
// accelerometer biases (appendix B, eqs. 69-70) so a bias change needs no re-integration, and
// their covariance propagated sample by sample (eq. 63). The same first-order treatment covers
// scale-factor errors (measured = (1 + s) true + b per axis, so the true increment is
// meas - b dt - diag(meas) s to first order): the Jacobians are kept for the 12 IMU error
// parameters [gyro bias, accel bias, gyro scale, accel scale] together.
//
// The earth's rotation, which Forster neglects, is taken out of each gyro increment as a known
// term through the starting attitude: omega_ib - C_bt omega_ie (the attitude there is known to
// far better than the 1e-5 relative size of this term needs).
#pragma once

#include <Eigen/Core>

namespace navfuse::calib {

struct ImuNoiseDensity {
  double gyro_rad_rts = 1e-4;   // angle random walk
  double accel_mps_rts = 1e-3;  // velocity random walk
};

class ImuPreintegration {
 public:
  // Integrates about the bias values bg0, ba0 (sensor frame); `c_tb_i` is the attitude at i
  // (tangent <- body), used only for the earth-rate term.
  ImuPreintegration(const Eigen::Vector3d& bg0, const Eigen::Vector3d& ba0, const Eigen::Matrix3d& c_tb_i,
                    const Eigen::Vector3d& earth_rate_t, const ImuNoiseDensity& noise);

  // One IMU sample: angle and velocity increments over dt_s (rates times dt for a rate IMU).
  void add(const Eigen::Vector3d& dtheta_rad, const Eigen::Vector3d& dvel_mps, double dt_s);
  // The allowance for biases that are not quite constant over the interval: a random walk of
  // these std devs per sqrt(s) added to the covariance of the increments.
  void add_bias_drift(double gyro_rps_rts, double accel_mps2_rts);

  double dt() const { return dt_; }
  const Eigen::Matrix3d& delta_r() const { return dr_; }
  const Eigen::Vector3d& delta_v() const { return dv_; }
  const Eigen::Vector3d& delta_p() const { return dp_; }
  // d[rotation; velocity; position] / d[bg, ba, sg, sa] at the linearisation point (biases bg0,
  // ba0, scale errors zero): 9 x 12.
  const Eigen::Matrix<double, 9, 12>& jacobian() const { return jac_; }
  const Eigen::Vector3d& bg0() const { return bg0_; }
  const Eigen::Vector3d& ba0() const { return ba0_; }
  // Covariance of [rotation, velocity, position] increments (9x9).
  const Eigen::Matrix<double, 9, 9>& covariance() const { return cov_; }

 private:
  Eigen::Vector3d bg0_, ba0_;
  Eigen::Matrix3d c_bt_i_;
  Eigen::Vector3d earth_rate_t_;
  ImuNoiseDensity noise_;
  double dt_ = 0.0;
  Eigen::Matrix3d dr_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d dv_ = Eigen::Vector3d::Zero(), dp_ = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 9, 12> jac_ = Eigen::Matrix<double, 9, 12>::Zero();
  Eigen::Matrix<double, 9, 9> cov_ = Eigen::Matrix<double, 9, 9>::Zero();
};

// Columns of ImuPreintegration::jacobian().
inline constexpr int kGyroBias = 0, kAccelBias = 3, kGyroScale = 6, kAccelScale = 9;

// The SO(3) right Jacobian J_r(phi) (Chirikjian 2011; Forster eq. 8).
Eigen::Matrix3d right_jacobian(const Eigen::Vector3d& phi);

}  // namespace navfuse::calib

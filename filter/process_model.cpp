#include "filter/process_model.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

StateVector process_noise_density(const FilterOptions& o) {
  StateVector q = StateVector::Zero();
  const auto& n = o.imu;
  q.segment<3>(sx::kVel).setConstant(n.accel_vrw_mps_rts * n.accel_vrw_mps_rts);
  q.segment<3>(sx::kAtt).setConstant(n.gyro_arw_rad_rts * n.gyro_arw_rad_rts);
  // First-order Gauss-Markov driving noise q = 2 sigma^2 / tau keeps the stationary std at sigma
  // (Brown & Hwang, "Introduction to Random Signals and Applied Kalman Filtering", GM process).
  q.segment<3>(sx::kGyroBias).setConstant(2.0 * n.gyro_bias_std_rps * n.gyro_bias_std_rps /
                                          n.gyro_bias_corr_time_s);
  q.segment<3>(sx::kAccelBias).setConstant(2.0 * n.accel_bias_std_mps2 * n.accel_bias_std_mps2 /
                                           n.accel_bias_corr_time_s);
  // Slow random walks for calibration states so they can follow temperature drift without
  // freezing: 1e-4 / sqrt(h) on scale factors, 0.01 deg / sqrt(h) on mounting.
  const double sf_rw = 1e-4 / 60.0;
  q(sx::kWheelScale) = sf_rw * sf_rw;
  q.segment<3>(sx::kGyroScale).setConstant(sf_rw * sf_rw);
  q.segment<3>(sx::kAccelScale).setConstant(sf_rw * sf_rw);
  const double mount_rw = 0.01 * rot::kDegToRad / 60.0;
  q(sx::kMountPitch) = mount_rw * mount_rw;
  q(sx::kMountYaw) = mount_rw * mount_rw;
  for (int i = 0; i < sx::kCount; ++i) {
    if (!o.states.is_active(i)) q(i) = 0.0;
  }
  return q;
}

namespace {

// P <- Phi P Phi^T + Q_d on the leading N x N block, with fixed-size matrices so the compiler
// unrolls and vectorises the products (the per-step cost that dominates the filter loop).
template <int N>
void discrete_step(Covariance& p, const Covariance& f, const StateVector& q, double t) {
  using Block = Eigen::Matrix<double, N, N>;
  const Block ft = f.template topLeftCorner<N, N>() * t;
  Block phi = Block::Identity() + ft;
  phi.noalias() += 0.5 * ft * ft;
  // Q_d = Q T + (F Q + Q F^T) T^2 / 2: the first two terms of the series for
  // integral(Phi Q Phi^T), exact enough at T <= 50 ms.
  Block qd = (ft * q.template head<N>().asDiagonal()) * (0.5 * t);
  qd = (qd + qd.transpose()).eval();
  qd.diagonal() += q.template head<N>() * t;
  Block tmp;
  tmp.noalias() = phi * p.template topLeftCorner<N, N>();
  Block next = qd;
  next.noalias() += tmp * phi.transpose();
  p.template topLeftCorner<N, N>() = 0.5 * (next + next.transpose());
}

}  // namespace

void propagate_covariance(Covariance& p, int n, const NavState& x, const LocalEarth& earth,
                          const ProcessAccumulator& step, const StateVector& q) {
  const double t = step.dt_s;
  if (t <= 0.0) return;
  const Eigen::Matrix3d c_nb = x.q_nb.toRotationMatrix();
  const Eigen::Vector3d f_b = step.dvel_mps / t;
  const Eigen::Vector3d w_b = step.dtheta_rad / t;
  const Eigen::Vector3d f_n = c_nb * f_b;
  const Eigen::Vector3d w_ie = earth.earth_rate_ned_rps;
  const Eigen::Vector3d w_en = earth.transport_rate(x.vel_ned_mps);
  const double rn_h = earth.radii.meridian_m + x.height_m;
  const double re_h = earth.radii.prime_vertical_m + x.height_m;
  const double tan_lat = std::tan(x.lat_rad);
  const double omega = w_ie.norm();

  Covariance f = Covariance::Zero();
  // Position: d(dr)/dt = dv (the curvature terms are O(v/R) ~ 1e-6 /s and are dropped).
  f.block<3, 3>(sx::kPos, sx::kVel).setIdentity();
  // Velocity: Coriolis, the vertical gravity gradient 2 g / R (the term that makes the vertical
  // channel unstable), tilt coupling [f^n x] and the accelerometer errors.
  f.block<3, 3>(sx::kVel, sx::kVel) = -rot::skew(2.0 * w_ie + w_en);
  f(sx::kVel + 2, sx::kPos + 2) =
      2.0 * earth.gravity_ned_mps2.z() / (std::sqrt(earth.radii.meridian_m * earth.radii.prime_vertical_m) + x.height_m);
  f.block<3, 3>(sx::kVel, sx::kAtt) = rot::skew(f_n);
  f.block<3, 3>(sx::kVel, sx::kAccelBias) = -c_nb;
  f.block<3, 3>(sx::kVel, sx::kAccelScale) = -c_nb * f_b.asDiagonal();
  // Attitude: phi_dot = -w_in x phi + d(w_in) + C_nb (d b_g + diag(w) d s_g), with d(w_in) the
  // earth-rate change with latitude and the transport-rate change with velocity.
  f.block<3, 3>(sx::kAtt, sx::kAtt) = -rot::skew(w_ie + w_en);
  f(sx::kAtt + 0, sx::kPos + 0) = -omega * std::sin(x.lat_rad) / rn_h;
  f(sx::kAtt + 2, sx::kPos + 0) = -omega * std::cos(x.lat_rad) / rn_h;
  f(sx::kAtt + 0, sx::kVel + 1) = 1.0 / re_h;
  f(sx::kAtt + 1, sx::kVel + 0) = -1.0 / rn_h;
  f(sx::kAtt + 2, sx::kVel + 1) = -tan_lat / re_h;
  f.block<3, 3>(sx::kAtt, sx::kGyroBias) = c_nb;
  f.block<3, 3>(sx::kAtt, sx::kGyroScale) = c_nb * w_b.asDiagonal();
  // Biases: F = 0. The bias is a turn-on constant plus a slow Gauss-Markov part; a -1/tau decay
  // on the sum would pull the (large) turn-on estimate toward zero and decorrelate it from the
  // tilt it was levelled with. Over the filter's horizons (tau >= minutes) the GM part is a random
  // walk with the GM driving noise, which process_noise_density supplies.

  switch (n) {  // the possible active dimensions (StateSelection::active_dimension)
    case sx::kCoreCount: return discrete_step<sx::kCoreCount>(p, f, q, t);
    case sx::kWheelScale + 1: return discrete_step<sx::kWheelScale + 1>(p, f, q, t);
    case sx::kMountYaw + 1: return discrete_step<sx::kMountYaw + 1>(p, f, q, t);
    case sx::kLeverArm + 3: return discrete_step<sx::kLeverArm + 3>(p, f, q, t);
    case sx::kGyroScale + 3: return discrete_step<sx::kGyroScale + 3>(p, f, q, t);
    default: return discrete_step<sx::kCount>(p, f, q, t);
  }
}

}  // namespace navfuse::filter

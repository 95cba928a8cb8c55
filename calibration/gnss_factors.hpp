// GNSS residuals at an epoch: the antenna's position (and velocity) predicted from the IMU state
// through the lever arm, the mounting and the IMU clock offset, minus the receiver's, whitened by
// the receiver's covariance (scaled as the filter scales it).
//
// The fix at GNSS time t_g is the state at IMU stamp t_g - dt_imu (imu.time_offset_s: added to
// IMU stamps to put them on the GNSS base). The state sits at IMU stamp t_k close to it, so with
// tau = t_g - t_k the antenna is moved by its velocity over tau - dt_imu (p(t + dt) ~ p + v dt,
// the first-order shift; tau - dt_imu stays within the IMU period plus the offset's correction).
//   antenna position  p + R C_sv l + v_a (tau - dt_imu),  v_a = v + R (omega_s x C_sv l)
//   antenna velocity  v_a + a (tau - dt_imu)
// omega_s (the rate w.r.t. the earth) and a (the acceleration) at the epoch are known terms from
// the starting solution's change over a few IMU samples (calibration_epochs.cpp). The mounting is the configured one turned by the residual vehicle pitch and
// yaw (mounting_dcm); its roll is held (unobservable from odometry).
// Blocks: p, v, q, lever arm (vehicle frame), mounting residual [pitch, yaw], dt_imu.
#pragma once

#include <cmath>
#include <cstdint>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "calibration/mounting_rotation.hpp"

namespace navfuse::calib {

// What GNSS factors share at one epoch.
struct EpochKnowns {
  Eigen::Matrix3d c_vs0 = Eigen::Matrix3d::Identity();  // the configured mounting, sensor -> vehicle
  Eigen::Vector3d rate_s_rps = Eigen::Vector3d::Zero();   // angular rate w.r.t. the earth, sensor frame
  Eigen::Vector3d accel_t_mps2 = Eigen::Vector3d::Zero();  // acceleration, tangent frame
};

// U with U^T U = cov^-1.
inline Eigen::Matrix3d sqrt_information(const Eigen::Matrix3d& cov) {
  const Eigen::Matrix3d info = cov.inverse();
  return Eigen::LLT<Eigen::Matrix3d>(0.5 * (info + info.transpose())).matrixU();
}

template <typename T>
Eigen::Matrix<T, 3, 1> antenna_velocity(const Eigen::Matrix<T, 3, 1>& v, const Eigen::Matrix<T, 3, 3>& r,
                                        const Eigen::Matrix<T, 3, 1>& lever_s, const EpochKnowns& k) {
  return v + r * cross(Eigen::Matrix<T, 3, 1>(k.rate_s_rps.cast<T>()), lever_s);
}

// A square-root information matrix given as such: rows may be zero (an axis the measurement does
// not have, as external aiding's per-axis validity says), which no covariance can express.
struct SqrtInformation {
  Eigen::Matrix3d u;
};

// Per-axis std devs along the rows of `axes_from_t` (tangent -> the measurement's axes), an axis
// whose bit is clear in `valid_axes` weighted zero: U = diag(1/std) A.
inline SqrtInformation axis_sqrt_information(const Eigen::Vector3d& std, std::uint32_t valid_axes,
                                             const Eigen::Matrix3d& axes_from_t) {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    if ((valid_axes >> i & 1u) != 0) w[i] = 1.0 / std[i];
  }
  return {w.asDiagonal() * axes_from_t};
}

// Also used for external aiding's positions at their own (fixed) lever arms.
class GnssPositionFactor {
 public:
  GnssPositionFactor(const Eigen::Vector3d& pos_t, const Eigen::Matrix3d& cov_t, double tau_s, const EpochKnowns& k)
      : pos_(pos_t), sqrt_info_(sqrt_information(cov_t)), tau_(tau_s), k_(k) {}
  GnssPositionFactor(const Eigen::Vector3d& pos_t, const SqrtInformation& w, double tau_s, const EpochKnowns& k)
      : pos_(pos_t), sqrt_info_(w.u), tau_(tau_s), k_(k) {}

  template <typename T>
  bool operator()(const T* p, const T* v, const T* q, const T* lever, const T* mount, const T* dt, T* out) const {
    using V3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Matrix<T, 3, 3> r = Eigen::Map<const Eigen::Quaternion<T>>(q).toRotationMatrix();
    const V3 lever_s = mounting_dcm(mount, k_.c_vs0).transpose() * Eigen::Map<const V3>(lever);
    const V3 va = antenna_velocity(V3(Eigen::Map<const V3>(v)), r, lever_s, k_);
    const V3 predicted = Eigen::Map<const V3>(p) + r * lever_s + va * (T(tau_) - dt[0]);
    Eigen::Map<V3> res(out);
    res = sqrt_info_.cast<T>() * (predicted - pos_.cast<T>());
    return true;
  }

 private:
  Eigen::Vector3d pos_;
  Eigen::Matrix3d sqrt_info_;
  double tau_;
  EpochKnowns k_;
};

class GnssVelocityFactor {
 public:
  GnssVelocityFactor(const Eigen::Vector3d& vel_t, const Eigen::Matrix3d& cov_t, double tau_s, const EpochKnowns& k)
      : vel_(vel_t), sqrt_info_(sqrt_information(cov_t)), tau_(tau_s), k_(k) {}
  GnssVelocityFactor(const Eigen::Vector3d& vel_t, const SqrtInformation& w, double tau_s, const EpochKnowns& k)
      : vel_(vel_t), sqrt_info_(w.u), tau_(tau_s), k_(k) {}

  template <typename T>
  bool operator()(const T* v, const T* q, const T* lever, const T* mount, const T* dt, T* out) const {
    using V3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Matrix<T, 3, 3> r = Eigen::Map<const Eigen::Quaternion<T>>(q).toRotationMatrix();
    const V3 lever_s = mounting_dcm(mount, k_.c_vs0).transpose() * Eigen::Map<const V3>(lever);
    const V3 predicted =
        antenna_velocity(V3(Eigen::Map<const V3>(v)), r, lever_s, k_) + k_.accel_t_mps2.cast<T>() * (T(tau_) - dt[0]);
    Eigen::Map<V3> res(out);
    res = sqrt_info_.cast<T>() * (predicted - vel_.cast<T>());
    return true;
  }

 private:
  Eigen::Vector3d vel_;
  Eigen::Matrix3d sqrt_info_;
  double tau_;
  EpochKnowns k_;
};

// Dual-antenna heading (GnssHeading): the azimuth of the baseline from the primary to the
// secondary antenna, fixed in the vehicle frame (b_v, from the two configured lever arms, as the
// filter's gnss_heading.hpp takes it; the estimated primary lever arm does not move it). Through
// the mounting, b_s = C_vs^T b_v is what the IMU's attitude turns: the heading sees the mounting's
// yaw directly, with or without odometry. Moved over tau - dt_imu by the rate as the position is:
//   b_n = C_nt R (b_s + (omega_s x b_s)(tau - dt_imu))
// The residual is the signed angle from the measured azimuth to b_n's, atan2 of the horizontal
// cross and dot products (no wrap at +-pi), over the reported std. The baseline's elevation is
// not used (it sees the mounting's pitch only across a long baseline's few-degree tilt).
// External aiding's heading (ExternalHeading) is the same with the vehicle's x axis as baseline.
// Blocks: q, mounting residual [pitch, yaw], dt_imu.
class GnssHeadingFactor {
 public:
  GnssHeadingFactor(double heading_rad, double std_rad, const Eigen::Vector3d& baseline_v,
                    const Eigen::Matrix3d& c_nt, double tau_s, const EpochKnowns& k)
      : cos_(std::cos(heading_rad)), sin_(std::sin(heading_rad)), inv_std_(1.0 / std_rad), baseline_v_(baseline_v),
        c_nt_(c_nt), tau_(tau_s), k_(k) {}

  template <typename T>
  bool operator()(const T* q, const T* mount, const T* dt, T* out) const {
    using V3 = Eigen::Matrix<T, 3, 1>;
    using std::atan2;
    const Eigen::Matrix<T, 3, 3> r = Eigen::Map<const Eigen::Quaternion<T>>(q).toRotationMatrix();
    const V3 b_s = mounting_dcm(mount, k_.c_vs0).transpose() * baseline_v_.cast<T>();
    const V3 moved_s = b_s + cross(V3(k_.rate_s_rps.cast<T>()), b_s) * (T(tau_) - dt[0]);
    const V3 b_n = c_nt_.cast<T>() * (r * moved_s);
    out[0] = atan2(T(cos_) * b_n.y() - T(sin_) * b_n.x(), T(cos_) * b_n.x() + T(sin_) * b_n.y()) * T(inv_std_);
    return true;
  }

 private:
  double cos_, sin_, inv_std_;
  Eigen::Vector3d baseline_v_;
  Eigen::Matrix3d c_nt_;
  double tau_;
  EpochKnowns k_;
};

}  // namespace navfuse::calib

namespace navfuse::calib {

// A prior on an N-vector parameter: the lever arm around its configured value, the mounting
// pitch and yaw residuals around zero, the IMU scale factors around zero (their data-sheet std: x and y
// gyro scale are barely seen on a drive).
//
// The lever arm's: a broad prior around its configured value. The component along the vertical
// is seen only through changes of roll and pitch (p_z + l_z is what GNSS measures when level):
// on a flat drive nothing else fixes it, and without the prior the solver wanders along that
// direction. The prior's std then comes back as the estimate's: "not observed". The mounting's
// likewise: its pitch is seen only through the NHC's vertical velocity.
template <int N>
class VectorPrior {
 public:
  VectorPrior(const Eigen::Matrix<double, N, 1>& mean, double std)
      : mean_(mean), inv_std_(Eigen::Matrix<double, N, 1>::Constant(1.0 / std)) {}
  // One std per component.
  VectorPrior(const Eigen::Matrix<double, N, 1>& mean, const Eigen::Matrix<double, N, 1>& std)
      : mean_(mean), inv_std_(std.cwiseInverse()) {}
  template <typename T>
  bool operator()(const T* x, T* out) const {
    for (int i = 0; i < N; ++i) out[i] = (x[i] - T(mean_[i])) * T(inv_std_[i]);
    return true;
  }

 private:
  Eigen::Matrix<double, N, 1> mean_;
  Eigen::Matrix<double, N, 1> inv_std_;
};

}  // namespace navfuse::calib

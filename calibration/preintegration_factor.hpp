// The IMU factor between epochs i and j (Forster et al. 2017 eq. 45, with the bias update of
// eq. 44, extended to scale factors, imu_preintegration.hpp): residuals of rotation, velocity and position between the states and the
// preintegrated increments (imu_preintegration.hpp), whitened by their covariance.
//
// In the earth-fixed tangent frame (local_frame.hpp) the velocity equation has the Coriolis term
// -2 omega_ie x v besides gravity (Groves 2nd ed. eq. 5.35 in an earth-fixed frame). Its integral
// over the interval is exactly -2 omega_ie x (p_j - p_i); its double integral is taken as
// -omega_ie x (p_j - p_i) dt (velocity linear over the interval: 1e-4 m/s^2 at most, so
// micrometres). Gravity is the mean of its values at the two ends (1e-6 m/s^2 per metre).
// With e = [bg - bg0, ba - ba0, sg, sa] the IMU error parameters' change:
//   r_R = Log( (dR Exp(J_R e))^T R_i^T R_j )
//   r_v = R_i^T (v_j - v_i - g dt + 2 w x (p_j - p_i)) - (dv + J_v e)
//   r_p = R_i^T (p_j - p_i - v_i dt - g dt^2 / 2 + w x (p_j - p_i) dt) - (dp + J_p e)
// Parameter blocks: p_i, v_i, q_i, p_j, v_j, q_j (q: Eigen quaternion x y z w, tangent <- sensor),
// gyro bias, accel bias, gyro scale, accel scale.
#pragma once

#include <ceres/rotation.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "calibration/imu_preintegration.hpp"
#include "calibration/mounting_rotation.hpp"

namespace navfuse::calib {

class PreintegrationFactor {
 public:
  PreintegrationFactor(const ImuPreintegration& pre, const Eigen::Vector3d& gravity_t, const Eigen::Vector3d& earth_rate_t)
      : pre_(pre), g_(gravity_t), w_(earth_rate_t) {
    // Whitening: U with U^T U = cov^-1, so |U r|^2 is the Mahalanobis norm.
    const Eigen::Matrix<double, 9, 9> info = pre.covariance().inverse();
    sqrt_info_ = Eigen::LLT<Eigen::Matrix<double, 9, 9>>(0.5 * (info + info.transpose())).matrixU();
  }

  template <typename T>
  bool operator()(const T* p_i, const T* v_i, const T* q_i, const T* p_j, const T* v_j, const T* q_j,
                  const T* bg, const T* ba, const T* sg, const T* sa, T* out) const {
    using V3 = Eigen::Matrix<T, 3, 1>;
    using M3 = Eigen::Matrix<T, 3, 3>;
    const Eigen::Map<const V3> pi(p_i), vi(v_i), pj(p_j), vj(v_j), bgm(bg), bam(ba), sgm(sg), sam(sa);
    const M3 ri = Eigen::Map<const Eigen::Quaternion<T>>(q_i).toRotationMatrix();
    const M3 rj = Eigen::Map<const Eigen::Quaternion<T>>(q_j).toRotationMatrix();
    Eigen::Matrix<T, 12, 1> e;
    e << bgm - pre_.bg0().cast<T>(), bam - pre_.ba0().cast<T>(), sgm, sam;
    const Eigen::Matrix<T, 9, 1> lin = pre_.jacobian().cast<T>() * e;
    const T dt(pre_.dt());

    const V3 corr = lin.template head<3>();
    M3 exp_corr;
    ceres::AngleAxisToRotationMatrix(corr.data(), exp_corr.data());  // column-major, as Eigen's default
    const M3 r_err = (pre_.delta_r().cast<T>() * exp_corr).transpose() * ri.transpose() * rj;
    V3 r_rot;
    ceres::RotationMatrixToAngleAxis(r_err.data(), r_rot.data());

    const V3 g = g_.cast<T>(), w = w_.cast<T>();
    const V3 dpos = pj - pi;
    const V3 r_vel = ri.transpose() * (vj - vi - g * dt + T(2.0) * cross(w, dpos)) -
                     (pre_.delta_v().cast<T>() + lin.template segment<3>(3));
    const V3 r_pos = ri.transpose() * (dpos - vi * dt - T(0.5) * g * dt * dt + cross(w, dpos) * dt) -
                     (pre_.delta_p().cast<T>() + lin.template tail<3>());
    Eigen::Matrix<T, 9, 1> r;
    r << r_rot, r_vel, r_pos;
    Eigen::Map<Eigen::Matrix<T, 9, 1>> res(out);
    res = sqrt_info_.cast<T>() * r;
    return true;
  }

 private:
  ImuPreintegration pre_;
  Eigen::Vector3d g_, w_;
  Eigen::Matrix<double, 9, 9> sqrt_info_;
};

}  // namespace navfuse::calib

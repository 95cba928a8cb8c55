// External aiding's velocity in the vehicle frame (VelocityFrame::kVehicle: MIP (0x13,0x2A) Body
// Frame Velocity, what a radar, a visual odometer or pre-processed wheel speed sends; MIP digest
// "Body-frame velocity semantics"): the velocity of the point at the aiding's lever arm l in
// vehicle axes, as the wheel speed and the NHC predict it (Groves 2nd ed. §6.3),
//   v_v = C_vs (v_s + omega_s x C_sv l),
// with the sensor-frame velocity v_s = R^T v moved over d = tau - dt_imu as the GNSS factors move
// the antenna: the velocity by the acceleration and the axes by the turn,
//   v_s(t + d) = R^T (v + a d) - omega_s x (R^T v) d
// (both terms first order: in a steady turn they cancel in the lateral axis, which is what keeps
// a car's sideways velocity zero). Its lateral and vertical components see the mounting's yaw and
// pitch as the NHC does, the forward one the clock offset through the acceleration. Weighted per
// vehicle axis, an axis the message marks invalid left out (axis_sqrt_information, identity axes).
// Blocks: v, q, mounting residual [pitch, yaw], dt_imu.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "calibration/gnss_factors.hpp"
#include "calibration/mounting_rotation.hpp"

namespace navfuse::calib {

class VehicleVelocityFactor {
 public:
  VehicleVelocityFactor(const Eigen::Vector3d& vel_v_mps, const SqrtInformation& w, const Eigen::Vector3d& lever_v_m,
                        double tau_s, const EpochKnowns& k)
      : vel_(vel_v_mps), sqrt_info_(w.u), lever_(lever_v_m), tau_(tau_s), k_(k) {}

  template <typename T>
  bool operator()(const T* v, const T* q, const T* mount, const T* dt, T* out) const {
    using V3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Matrix<T, 3, 3> r_t = Eigen::Map<const Eigen::Quaternion<T>>(q).toRotationMatrix().transpose();
    const Eigen::Matrix<T, 3, 3> c_vs = mounting_dcm(mount, k_.c_vs0);
    const V3 rate_s(k_.rate_s_rps.cast<T>());
    const V3 v_t = Eigen::Map<const V3>(v);
    const T d = T(tau_) - dt[0];
    const V3 v_s = r_t * (v_t + k_.accel_t_mps2.cast<T>() * d) - cross(rate_s, V3(r_t * v_t)) * d;
    const V3 predicted = c_vs * (v_s + cross(rate_s, V3(c_vs.transpose() * lever_.cast<T>())));
    Eigen::Map<V3> res(out);
    res = sqrt_info_.cast<T>() * (predicted - vel_.cast<T>());
    return true;
  }

 private:
  Eigen::Vector3d vel_;
  Eigen::Matrix3d sqrt_info_;
  Eigen::Vector3d lever_;
  double tau_;
  EpochKnowns k_;
};

}  // namespace navfuse::calib

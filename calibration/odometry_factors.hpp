// Land-vehicle residuals at an epoch, in the vehicle frame: the velocity of a point at lever arm
// l is v_l = C_vs (R^T v + omega_s x C_sv l) (the rigid-body relation of Groves 2nd ed. §6.3).
//   wheel speed  s_meas - k v_l.x   at the wheel lever arm, k the odometer scale (measured / true)
//   NHC          v_l.y, v_l.z = 0   at the point that does not slip (Sukkarieh 2000; Shin 2001)
// The speed is the one measured at GNSS time t_k + dt_imu: interpolated at the starting offset
// and moved along its slope (the IMU's along-track acceleration) for the offset's change.
// C_vs is the configured mounting turned by the residual vehicle pitch and yaw (mounting_dcm).
// Blocks: wheel: v, q, mounting residual [pitch, yaw], k, dt_imu; NHC: v, q, mounting residual,
// the non-slip point.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "calibration/mounting_rotation.hpp"

namespace navfuse::calib {

template <typename T>
Eigen::Matrix<T, 3, 1> vehicle_velocity_at(const T* v, const T* q, const T* mount, const Eigen::Matrix3d& c_vs0,
                                           const Eigen::Vector3d& rate_s_rps, const Eigen::Matrix<T, 3, 1>& lever_v_m) {
  using V3 = Eigen::Matrix<T, 3, 1>;
  const Eigen::Matrix<T, 3, 3> r = Eigen::Map<const Eigen::Quaternion<T>>(q).toRotationMatrix();
  const Eigen::Matrix<T, 3, 3> c_vs = mounting_dcm(mount, c_vs0);
  const V3 lever_s = c_vs.transpose() * lever_v_m;
  return c_vs * (r.transpose() * Eigen::Map<const V3>(v) + cross(V3(rate_s_rps.cast<T>()), lever_s));
}

class WheelSpeedFactor {
 public:
  // speed_mps / slope_mps2: the measured speed at t_k + dt0 and its rate of change; dt0 the
  // offset it was interpolated at.
  WheelSpeedFactor(double speed_mps, double slope_mps2, double dt0_s, double std_mps, const Eigen::Matrix3d& c_vs0,
                   const Eigen::Vector3d& rate_s_rps, const Eigen::Vector3d& lever_v_m)
      : speed_(speed_mps), slope_(slope_mps2), dt0_(dt0_s), inv_std_(1.0 / std_mps), c_vs0_(c_vs0),
        rate_(rate_s_rps), lever_(lever_v_m) {}

  template <typename T>
  bool operator()(const T* v, const T* q, const T* mount, const T* scale, const T* dt, T* out) const {
    const Eigen::Matrix<T, 3, 1> vl = vehicle_velocity_at(v, q, mount, c_vs0_, rate_, Eigen::Matrix<T, 3, 1>(lever_.cast<T>()));
    const T measured = T(speed_) + T(slope_) * (dt[0] - T(dt0_));
    out[0] = (measured - scale[0] * vl.x()) * T(inv_std_);
    return true;
  }

 private:
  double speed_, slope_, dt0_, inv_std_;
  Eigen::Matrix3d c_vs0_;
  Eigen::Vector3d rate_, lever_;
};

// The non-slip point is a parameter block: held when the config gives it, estimated about it
// (with its nhc.lever_arm_std_m as prior) when the config only guesses it (the IMU).
class NhcFactor {
 public:
  NhcFactor(double lateral_std_mps, double vertical_std_mps, const Eigen::Matrix3d& c_vs0,
            const Eigen::Vector3d& rate_s_rps)
      : inv_lat_(1.0 / lateral_std_mps), inv_vert_(1.0 / vertical_std_mps), c_vs0_(c_vs0), rate_(rate_s_rps) {}

  template <typename T>
  bool operator()(const T* v, const T* q, const T* mount, const T* lever_v_m, T* out) const {
    const Eigen::Matrix<T, 3, 1> vl =
        vehicle_velocity_at(v, q, mount, c_vs0_, rate_, Eigen::Matrix<T, 3, 1>(Eigen::Map<const Eigen::Matrix<T, 3, 1>>(lever_v_m)));
    out[0] = vl.y() * T(inv_lat_);
    out[1] = vl.z() * T(inv_vert_);
    return true;
  }

 private:
  double inv_lat_, inv_vert_;
  Eigen::Matrix3d c_vs0_;
  Eigen::Vector3d rate_;
};

}  // namespace navfuse::calib

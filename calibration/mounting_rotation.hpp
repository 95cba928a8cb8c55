// The IMU mounting as a rotation the solver can differentiate: C_vs (sensor -> vehicle) from
// roll, pitch, yaw in the 3-2-1 order of the config key imu.mounting_rpy_deg, the same matrix as
// rot::dcm_from_rpy (core/rotation), written for any scalar so ceres::Jet passes through.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace navfuse::calib {

template <typename T>
Eigen::Matrix<T, 3, 3> dcm_from_rpy(const T& roll, const T& pitch, const T& yaw) {
  using std::cos;
  using std::sin;
  const T sr = sin(roll), cr = cos(roll), sp = sin(pitch), cp = cos(pitch), sy = sin(yaw), cy = cos(yaw);
  Eigen::Matrix<T, 3, 3> c;
  c << cp * cy, -cr * sy + sr * sp * cy, sr * sy + cr * sp * cy,
       cp * sy, cr * cy + sr * sp * sy, -sr * cy + cr * sp * sy,
       -sp, sr * cp, cr * cp;
  return c;
}

// Vector cross product for any scalar (Eigen's cross() on Jets is fine, this keeps the types
// explicit where a double vector meets a Jet one).
template <typename T>
Eigen::Matrix<T, 3, 1> cross(const Eigen::Matrix<T, 3, 1>& a, const Eigen::Matrix<T, 3, 1>& b) {
  return {a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x()};
}

}  // namespace navfuse::calib

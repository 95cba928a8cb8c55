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

// The mounting the calibration estimates: the configured C_vs0 (sensor -> vehicle) turned by a
// residual pitch, then yaw, about the vehicle's own y and z axes:
//   C_vs = R_z(residual[1]) R_y(residual[0]) C_vs0
// so the two angles are the vehicle frame's pitch and yaw errors whatever way the sensor is
// mounted, the errors the odometry and NHC residuals see (a wheel speed along the vehicle's x,
// no velocity along its y and z). The config key's Euler pitch and yaw are those axes only when
// the sensor's roll and yaw are near zero: for a sensor mounted x right, z up (roll 180, yaw -90,
// as on the walk and the held-out car) the Euler pitch turns the vehicle frame about its x axis,
// a roll that no residual sees, while the vehicle pitch is the Euler roll.
template <typename T>
Eigen::Matrix<T, 3, 3> mounting_dcm(const T* residual, const Eigen::Matrix3d& c_vs0) {
  return dcm_from_rpy(T(0), residual[0], residual[1]) * c_vs0.cast<T>();
}

// The config key's roll, pitch and yaw of the configured mounting turned by `residual`.
Eigen::Vector3d mounting_rpy(const Eigen::Vector2d& residual, const Eigen::Matrix3d& c_vs0);

// Their std devs from the residual's 2 x 2 covariance, through the Jacobian of the Euler angles
// (central differences; angles wrapped): for a sensor mounted x right, z up the vehicle pitch
// residual is the Euler roll's, so all three may be non-zero.
Eigen::Vector3d mounting_rpy_std(const Eigen::Vector2d& residual, const Eigen::Matrix2d& cov, const Eigen::Matrix3d& c_vs0);

// Vector cross product for any scalar (Eigen's cross() on Jets is fine, this keeps the types
// explicit where a double vector meets a Jet one).
template <typename T>
Eigen::Matrix<T, 3, 1> cross(const Eigen::Matrix<T, 3, 1>& a, const Eigen::Matrix<T, 3, 1>& b) {
  return {a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x()};
}

}  // namespace navfuse::calib

// Attitude conventions (DESIGN.md, contract): Hamilton quaternion q_nb rotates vehicle (FRD)
// vectors into NED, v_n = q_nb * v_b. Euler angles are the aerospace 3-2-1 sequence
// (yaw psi about z, then pitch theta about the new y, then roll phi about the new x), so that
// C_nb = Rz(psi) * Ry(theta) * Rx(phi) (Groves eq. 2.22 transposed; Titterton & Weston §3.6).
//
// Small helpers the filter uses: skew matrix, rotation vector <-> quaternion (exponential map),
// and frame swaps FRD<->FLU and NED<->ENU used when encoding other protocols' conventions.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace navfuse::rot {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kRadToDeg = 180.0 / kPi;

// Roll, pitch, yaw packed as a vector (x = roll, y = pitch, z = yaw), radians.
Eigen::Matrix3d dcm_from_rpy(const Eigen::Vector3d& rpy_rad);
Eigen::Quaterniond quat_from_rpy(const Eigen::Vector3d& rpy_rad);
// At pitch = +-90 deg (gimbal lock) roll is reported as 0 and yaw carries the combined angle.
Eigen::Vector3d rpy_from_dcm(const Eigen::Matrix3d& c_nb);
Eigen::Vector3d rpy_from_quat(const Eigen::Quaterniond& q_nb);

// Cross-product matrix: skew(a) * b == a.cross(b).
Eigen::Matrix3d skew(const Eigen::Vector3d& v);
// Rotation vector (axis * angle, rad) -> unit quaternion, exact for any angle (Taylor series
// near zero so that tiny increments lose no precision).
Eigen::Quaterniond quat_from_rotvec(const Eigen::Vector3d& rotvec_rad);
// Unit quaternion -> rotation vector with angle in [0, pi].
Eigen::Vector3d rotvec_from_quat(const Eigen::Quaterniond& q);

// FRD <-> FLU (x forward kept, y and z negated); its own inverse.
inline Eigen::Vector3d flu_from_frd(const Eigen::Vector3d& v) { return {v.x(), -v.y(), -v.z()}; }
inline Eigen::Vector3d frd_from_flu(const Eigen::Vector3d& v) { return {v.x(), -v.y(), -v.z()}; }
// NED <-> ENU (swap the horizontal axes, negate the vertical); its own inverse.
inline Eigen::Vector3d enu_from_ned(const Eigen::Vector3d& v) { return {v.y(), v.x(), -v.z()}; }
inline Eigen::Vector3d ned_from_enu(const Eigen::Vector3d& v) { return {v.y(), v.x(), -v.z()}; }
// Attitude of an FLU body in ENU for the same physical attitude as q_nb (FRD in NED):
// q_enu_flu = q(ENU<-NED) * q_nb * q(FRD<-FLU).
Eigen::Quaterniond quat_enu_flu_from_ned_frd(const Eigen::Quaterniond& q_nb);
Eigen::Quaterniond quat_ned_frd_from_enu_flu(const Eigen::Quaterniond& q_enu_flu);

// Wrap an angle to [-pi, pi).
double wrap_pi(double angle_rad);
// Wrap an angle to [0, 2 pi).
double wrap_two_pi(double angle_rad);

}  // namespace navfuse::rot

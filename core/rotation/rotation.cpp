#include "core/rotation/rotation.hpp"

#include <algorithm>
#include <cmath>

namespace navfuse::rot {

Eigen::Matrix3d dcm_from_rpy(const Eigen::Vector3d& rpy_rad) {
  // C_nb = Rz(yaw) Ry(pitch) Rx(roll): written out (Titterton & Weston eq. 3.47, transposed to
  // body->nav) to avoid three matrix products in the per-sample paths that call this.
  const double sr = std::sin(rpy_rad.x()), cr = std::cos(rpy_rad.x());
  const double sp = std::sin(rpy_rad.y()), cp = std::cos(rpy_rad.y());
  const double sy = std::sin(rpy_rad.z()), cy = std::cos(rpy_rad.z());
  Eigen::Matrix3d c;
  c << cp * cy, -cr * sy + sr * sp * cy, sr * sy + cr * sp * cy,
       cp * sy, cr * cy + sr * sp * sy, -sr * cy + cr * sp * sy,
       -sp, sr * cp, cr * cp;
  return c;
}

Eigen::Quaterniond quat_from_rpy(const Eigen::Vector3d& rpy_rad) {
  // q = qz(yaw) * qy(pitch) * qx(roll), the quaternion form of the same 3-2-1 sequence.
  const double hr = 0.5 * rpy_rad.x(), hp = 0.5 * rpy_rad.y(), hy = 0.5 * rpy_rad.z();
  const double sr = std::sin(hr), cr = std::cos(hr);
  const double sp = std::sin(hp), cp = std::cos(hp);
  const double sy = std::sin(hy), cy = std::cos(hy);
  Eigen::Quaterniond q(cr * cp * cy + sr * sp * sy,
                       sr * cp * cy - cr * sp * sy,
                       cr * sp * cy + sr * cp * sy,
                       cr * cp * sy - sr * sp * cy);
  if (q.w() < 0) q.coeffs() = -q.coeffs();  // canonical: non-negative scalar part
  return q;
}

Eigen::Vector3d rpy_from_dcm(const Eigen::Matrix3d& c) {
  // Inverse of dcm_from_rpy: c(2,0) = -sin(pitch). Clamp for rounding just past +-1.
  const double s = std::clamp(-c(2, 0), -1.0, 1.0);
  const double pitch = std::asin(s);
  if (std::abs(s) > 1.0 - 1e-12) {
    // Gimbal lock: only yaw -+ roll is observable; report roll 0.
    const double yaw = std::atan2(-c(0, 1), c(1, 1));
    return {0.0, pitch, yaw};
  }
  return {std::atan2(c(2, 1), c(2, 2)), pitch, std::atan2(c(1, 0), c(0, 0))};
}

Eigen::Vector3d rpy_from_quat(const Eigen::Quaterniond& q) {
  return rpy_from_dcm(q.normalized().toRotationMatrix());
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(),
       v.z(), 0, -v.x(),
       -v.y(), v.x(), 0;
  return m;
}

Eigen::Quaterniond quat_from_rotvec(const Eigen::Vector3d& rv) {
  const double angle_sq = rv.squaredNorm();
  double w, k;  // q = [cos(a/2), sin(a/2)/a * rv]
  if (angle_sq < 1e-12) {
    // Taylor series to 4th order: cos(a/2) = 1 - a^2/8 + a^4/384, sin(a/2)/a = 1/2 - a^2/48 + a^4/3840.
    w = 1.0 - angle_sq / 8.0 + angle_sq * angle_sq / 384.0;
    k = 0.5 - angle_sq / 48.0 + angle_sq * angle_sq / 3840.0;
  } else {
    const double angle = std::sqrt(angle_sq);
    w = std::cos(0.5 * angle);
    k = std::sin(0.5 * angle) / angle;
  }
  return Eigen::Quaterniond(w, k * rv.x(), k * rv.y(), k * rv.z());
}

Eigen::Vector3d rotvec_from_quat(const Eigen::Quaterniond& q_in) {
  Eigen::Quaterniond q = q_in.normalized();
  if (q.w() < 0) q.coeffs() = -q.coeffs();  // shortest rotation: angle in [0, pi]
  const Eigen::Vector3d v = q.vec();
  const double s = v.norm();
  if (s < 1e-12) return 2.0 * v / q.w();  // angle ~ 2 s: first-order exact to 1e-24
  const double angle = 2.0 * std::atan2(s, q.w());
  return v * (angle / s);
}

Eigen::Quaterniond quat_enu_flu_from_ned_frd(const Eigen::Quaterniond& q_nb) {
  // C_enu_ned swaps x/y and negates z; C_frd_flu negates y and z. Both are proper rotations:
  // ENU<-NED is a rotation of pi about (1,1,0)/sqrt2, FRD<-FLU is a rotation of pi about x.
  static const Eigen::Quaterniond q_enu_ned(0.0, std::sqrt(0.5), std::sqrt(0.5), 0.0);
  static const Eigen::Quaterniond q_frd_flu(0.0, 1.0, 0.0, 0.0);
  Eigen::Quaterniond q = q_enu_ned * q_nb * q_frd_flu;
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return q.normalized();
}

Eigen::Quaterniond quat_ned_frd_from_enu_flu(const Eigen::Quaterniond& q_enu_flu) {
  static const Eigen::Quaterniond q_ned_enu(0.0, std::sqrt(0.5), std::sqrt(0.5), 0.0);  // self-inverse
  static const Eigen::Quaterniond q_flu_frd(0.0, 1.0, 0.0, 0.0);
  Eigen::Quaterniond q = q_ned_enu * q_enu_flu * q_flu_frd;
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return q.normalized();
}

double wrap_pi(double a) {
  a = std::fmod(a + kPi, 2.0 * kPi);
  if (a < 0) a += 2.0 * kPi;
  return a - kPi;
}

double wrap_two_pi(double a) {
  a = std::fmod(a, 2.0 * kPi);
  if (a < 0) a += 2.0 * kPi;
  return a;
}

}  // namespace navfuse::rot

#include "filter/measurements/state_view.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

Eigen::Vector3d position_difference_ned_m(const StateView& s, double lat_rad, double lon_rad,
                                          double height_m) {
  const double h = s.x.height_m;
  return {(s.x.lat_rad - lat_rad) * (s.earth.radii.meridian_m + h),
          rot::wrap_pi(s.x.lon_rad - lon_rad) * (s.earth.radii.prime_vertical_m + h) *
              std::cos(s.x.lat_rad),
          -(h - height_m)};
}

AzimuthModel azimuth_of(const StateView& s, const Eigen::Vector3d& direction_b) {
  const Eigen::Vector3d b_n = s.c_nb * direction_b;
  const double horiz_sq = b_n.x() * b_n.x() + b_n.y() * b_n.y();
  AzimuthModel m;
  m.azimuth_rad = std::atan2(b_n.y(), b_n.x());
  if (horiz_sq <= 1e-12) return m;
  // C_hat b - C b = (C b) x phi = [b_n x] phi; d(atan2(y, x)) = (x dy - y dx) / (x^2 + y^2).
  const Eigen::RowVector3d d_dbn(-b_n.y() / horiz_sq, b_n.x() / horiz_sq, 0.0);
  m.d_dphi = d_dbn * rot::skew(b_n);
  return m;
}

BodyVelocityModel body_velocity_at(const StateView& s, const Eigen::Vector3d& l, bool odometry_frame) {
  const Eigen::Matrix3d c_bn = s.c_nb.transpose();
  // Rate of the vehicle relative to the earth: w_eb = w_ib - C_bn w_ie.
  const Eigen::Vector3d w_eb = s.rate_b_rps - c_bn * s.earth.earth_rate_ned_rps;
  const Eigen::Vector3d v_b = c_bn * s.x.vel_ned_mps + w_eb.cross(l);
  Eigen::Matrix<double, 3, sx::kCount> j = Eigen::Matrix<double, 3, sx::kCount>::Zero();
  // C_hat^T = C^T (I + [phi x]):  C_hat^T v - C^T v = -C^T [v x] phi.
  j.block<3, 3>(0, sx::kVel) = c_bn;
  j.block<3, 3>(0, sx::kAtt) = -c_bn * rot::skew(s.x.vel_ned_mps);
  // w_hat = w - d b_g:  -(d b_g x l) = [l x] d b_g.
  j.block<3, 3>(0, sx::kGyroBias) = rot::skew(l);

  BodyVelocityModel m;
  if (!odometry_frame) {
    m.vel_mps = v_b;
    m.jacobian = j;
    return m;
  }
  const Eigen::Vector3d alpha(0.0, s.x.mount_pitch_rad, s.x.mount_yaw_rad);
  const Eigen::Matrix3d r_m = Eigen::Matrix3d::Identity() - rot::skew(alpha);
  m.vel_mps = r_m * v_b;
  m.jacobian.noalias() = r_m.lazyProduct(j);
  // R_m_hat v - R_m v = -(d alpha x v) = [v x] d alpha.
  const Eigen::Matrix3d d_alpha = rot::skew(v_b);
  m.jacobian.col(sx::kMountPitch) = d_alpha.col(1);
  m.jacobian.col(sx::kMountYaw) = d_alpha.col(2);
  return m;
}

}  // namespace navfuse::filter

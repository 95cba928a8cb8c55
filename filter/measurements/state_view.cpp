#include "filter/measurements/state_view.hpp"

#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

PointPrediction point_at(const StateView& s, const Eigen::Vector3d& lever_arm_m) {
  // Predicted position at the measurement time (the state is at most one IMU interval away, so a
  // constant-velocity shift is exact to the millimetre).
  return {s.x.lat_rad, s.x.lon_rad, s.x.height_m, s.c_nb * lever_arm_m + s.x.vel_ned_mps * s.shift_s};
}

Eigen::Vector3d point_minus_llh_ned_m(const StateView& s, const PointPrediction& p, double lat_rad,
                                      double lon_rad, double height_m) {
  const double h = p.height_m;
  const Eigen::Vector3d origin_minus_z(
      (p.lat_rad - lat_rad) * (s.earth.radii.meridian_m + h),
      rot::wrap_pi(p.lon_rad - lon_rad) * (s.earth.radii.prime_vertical_m + h) * std::cos(p.lat_rad),
      -(h - height_m));
  return origin_minus_z + p.offset_ned_m;
}

Eigen::Vector3d point_ecef_m(const PointPrediction& p) {
  return geo::ecef_from_llh(geo::llh_offset(geo::Llh{p.lat_rad, p.lon_rad, p.height_m}, p.offset_ned_m));
}

void point_jacobian(const StateView& s, const Eigen::Vector3d& lever_arm_m, Observation& obs) {
  obs.h.block<3, 3>(0, sx::kPos).setIdentity();
  obs.h.block<3, 3>(0, sx::kAtt) = rot::skew(s.c_nb * lever_arm_m);
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
  // The three non-zero blocks of the Jacobian (the model's BodyVelocityModel starts at zero):
  // C_hat^T = C^T (I + [phi x]):  C_hat^T v - C^T v = -C^T [v x] phi.
  const Eigen::Matrix3d d_vel = c_bn;
  const Eigen::Matrix3d d_att = -c_bn * rot::skew(s.x.vel_ned_mps);
  // w_hat = w - d b_g:  -(d b_g x l) = [l x] d b_g.
  const Eigen::Matrix3d d_gyro_bias = rot::skew(l);

  BodyVelocityModel m;
  if (!odometry_frame) {
    m.vel_mps = v_b;
    m.jacobian.block<3, 3>(0, sx::kVel) = d_vel;
    m.jacobian.block<3, 3>(0, sx::kAtt) = d_att;
    m.jacobian.block<3, 3>(0, sx::kGyroBias) = d_gyro_bias;
    return m;
  }
  const Eigen::Vector3d alpha(0.0, s.x.mount_pitch_rad, s.x.mount_yaw_rad);
  const Eigen::Matrix3d r_m = Eigen::Matrix3d::Identity() - rot::skew(alpha);
  m.vel_mps = r_m * v_b;
  m.jacobian.block<3, 3>(0, sx::kVel).noalias() = r_m.lazyProduct(d_vel);
  m.jacobian.block<3, 3>(0, sx::kAtt).noalias() = r_m.lazyProduct(d_att);
  m.jacobian.block<3, 3>(0, sx::kGyroBias).noalias() = r_m.lazyProduct(d_gyro_bias);
  // R_m_hat v - R_m v = -(d alpha x v) = [v x] d alpha.
  const Eigen::Matrix3d d_alpha = rot::skew(v_b);
  m.jacobian.col(sx::kMountPitch) = d_alpha.col(1);
  m.jacobian.col(sx::kMountYaw) = d_alpha.col(2);
  return m;
}

}  // namespace navfuse::filter

#include "filter/measurements/gnss_velocity.hpp"

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

Eigen::Vector3d antenna_velocity_ned_mps(const StateView& s, const Eigen::Vector3d& l) {
  return s.x.vel_ned_mps + s.c_nb * s.rate_b_rps.cross(l) - s.earth.earth_rate_ned_rps.cross(s.c_nb * l);
}

Observation antenna_velocity_observation(const StateView& s, const Eigen::Vector3d& l,
                                         const Eigen::Vector3d& measured, bool lever_arm_is_state) {
  Observation obs(3);
  obs.residual = antenna_velocity_ned_mps(s, l) - measured;
  obs.h.block<3, 3>(0, sx::kVel).setIdentity();
  obs.h.block<3, 3>(0, sx::kAtt) = rot::skew(s.c_nb * s.rate_b_rps.cross(l));
  // w_hat = w - d b_g: C (-(d b_g) x l) = C [l x] d b_g.
  obs.h.block<3, 3>(0, sx::kGyroBias) = s.c_nb * rot::skew(l);
  if (lever_arm_is_state) obs.h.block<3, 3>(0, sx::kLeverArm) = s.c_nb * rot::skew(s.rate_b_rps);
  return obs;
}

Observation gnss_velocity_observation(const StateView& s, const GnssVelocity& m, const Antenna& antenna) {
  Observation obs = antenna_velocity_observation(s, antenna.lever_arm_m, m.vel_ned_mps, antenna.lever_arm_is_state);
  // The fix is the antenna velocity at t + dt: v_ant + a dt, the acceleration an input of the view.
  obs.residual += s.accel_ned_mps2 * s.x.gnss_time_offset_s;
  obs.h.col(sx::kGnssTimeOffset) = s.accel_ned_mps2;
  if ((m.header.valid & GnssVelocity::kValidCovariance) != 0) {
    obs.r = m.cov_ned_m2ps2;
  } else {
    obs.r = Eigen::Vector3d(0.1, 0.1, 0.2).array().square().matrix().asDiagonal();
  }
  return obs;
}

}  // namespace navfuse::filter

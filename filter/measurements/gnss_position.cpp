#include "filter/measurements/gnss_position.hpp"

#include "filter/measurements/gnss_velocity.hpp"

namespace navfuse::filter {

Eigen::Vector3d default_gnss_position_std_m(GnssFixType fix) {
  switch (fix) {
    case GnssFixType::kRtkFixed: return {0.02, 0.02, 0.04};
    case GnssFixType::kRtkFloat: return {0.3, 0.3, 0.5};
    case GnssFixType::kPpp: return {0.1, 0.1, 0.2};
    case GnssFixType::kDgnss:
    case GnssFixType::kSbas: return {0.7, 0.7, 1.5};
    default: return {2.5, 2.5, 5.0};
  }
}

Eigen::Matrix3d gnss_position_cov_m2(const GnssPosition& m, double std_scale) {
  const Eigen::Matrix3d cov = (m.header.valid & GnssPosition::kValidCovariance) != 0
                                  ? m.cov_ned_m2
                                  : Eigen::Matrix3d(default_gnss_position_std_m(m.fix).array().square().matrix().asDiagonal());
  return std_scale == 1.0 ? cov : Eigen::Matrix3d(cov * (std_scale * std_scale));
}

Antenna antenna_of_receiver(const NavState& x, const Eigen::Vector3d& secondary_lever_arm_m,
                            std::uint8_t receiver_id) {
  if (receiver_id == 1 && !secondary_lever_arm_m.isZero()) return {secondary_lever_arm_m, false};
  return {x.gnss_lever_arm_m, true};
}

PointPrediction gnss_position_prediction(const StateView& s, const Antenna& antenna) {
  PointPrediction p = point_at(s, antenna.lever_arm_m);
  // The fix is the antenna at t + dt: v dt + a dt^2 / 2 with the (low-passed) acceleration of the
  // reference point. The second-order term is not small in a car park: a 3.5 m/s^2 turn moves the
  // antenna 2.7 cm off the tangent in 125 ms, always towards the turn's centre, a systematic error
  // where the offset is seen. The jerk term, and the lever arm's share of the acceleration, are
  // left out (the prior of dt is bounded for them: gnss.initial_time_offset_std_s).
  const double dt = s.x.gnss_time_offset_s;
  if (dt != 0.0) p.offset_ned_m += antenna_velocity_ned_mps(s, antenna.lever_arm_m) * dt + 0.5 * dt * dt * s.accel_ned_mps2;
  return p;
}

Observation gnss_position_observation(const StateView& s, const GnssPosition& m, const Antenna& antenna) {
  Observation obs(3);
  obs.residual =
      point_minus_llh_ned_m(s, gnss_position_prediction(s, antenna), m.lat_rad, m.lon_rad, m.height_m);
  point_jacobian(s, antenna.lever_arm_m, obs);
  if (antenna.lever_arm_is_state) obs.h.block<3, 3>(0, sx::kLeverArm) = s.c_nb;
  // d(v_ant dt): v_ant in the offset's column, dt times the antenna velocity's rows elsewhere.
  const double dt = s.x.gnss_time_offset_s;
  const Observation v_ant =
      antenna_velocity_observation(s, antenna.lever_arm_m, Eigen::Vector3d::Zero(), antenna.lever_arm_is_state);
  if (dt != 0.0) obs.h += dt * v_ant.h;
  obs.h.col(sx::kGnssTimeOffset) = v_ant.residual + dt * s.accel_ned_mps2;
  obs.r = gnss_position_cov_m2(m);
  if ((m.header.valid & GnssPosition::kValidHeight) == 0) obs.keep_rows(0b011);
  return obs;
}

}  // namespace navfuse::filter

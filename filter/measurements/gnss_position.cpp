#include "filter/measurements/gnss_position.hpp"

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

PointPrediction gnss_position_prediction(const StateView& s) { return point_at(s, s.x.gnss_lever_arm_m); }

Observation gnss_position_observation(const StateView& s, const GnssPosition& m) {
  Observation obs(3);
  obs.residual = point_minus_llh_ned_m(s, gnss_position_prediction(s), m.lat_rad, m.lon_rad, m.height_m);
  point_jacobian(s, s.x.gnss_lever_arm_m, obs);
  obs.h.block<3, 3>(0, sx::kLeverArm) = s.c_nb;
  if ((m.header.valid & GnssPosition::kValidCovariance) != 0) {
    obs.r = m.cov_ned_m2;
  } else {
    obs.r = default_gnss_position_std_m(m.fix).array().square().matrix().asDiagonal();
  }
  if ((m.header.valid & GnssPosition::kValidHeight) == 0) obs.keep_rows(0b011);
  return obs;
}

}  // namespace navfuse::filter

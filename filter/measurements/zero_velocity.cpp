#include "filter/measurements/zero_velocity.hpp"

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

Observation zero_velocity_observation(const StateView& s, double std_mps) {
  Observation obs(3);
  obs.residual = s.x.vel_ned_mps;  // h(x) = v_n, z = 0
  obs.h.block<3, 3>(0, sx::kVel).setIdentity();
  obs.r.diagonal().setConstant(std_mps * std_mps);
  return obs;
}

Eigen::Vector3d stationary_raw_rate_rps(const StateView& s) {
  // Raw gyro model (1 + s_g) w + b_g; at rest w = earth rate, so the scale term is ~1e-8 rad/s
  // and left out (kZeroRateNeglected).
  const Eigen::Matrix3d c_bn = s.c_nb.transpose();
  return s.x.gyro_bias_rps + c_bn * s.earth.earth_rate_ned_rps;
}

Observation zero_rate_observation(const StateView& s, const Eigen::Vector3d& mean_raw_rate,
                                  double std_rps) {
  Observation obs(3);
  obs.residual = stationary_raw_rate_rps(s) - mean_raw_rate;
  obs.h.block<3, 3>(0, sx::kGyroBias).setIdentity();
  const Eigen::Matrix3d c_bn = s.c_nb.transpose();
  obs.h.block<3, 3>(0, sx::kAtt) = -c_bn * rot::skew(s.earth.earth_rate_ned_rps);
  obs.r.diagonal().setConstant(std_rps * std_rps);
  return obs;
}

}  // namespace navfuse::filter

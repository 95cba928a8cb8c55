#include "filter/measurements/nonholonomic.hpp"

namespace navfuse::filter {

Observation nonholonomic_observation(const StateView& s, const Eigen::Vector3d& lever_arm_m,
                                     double lateral_std_mps, double vertical_std_mps) {
  const BodyVelocityModel v = body_velocity_at(s, lever_arm_m, true);
  Observation obs(2);
  obs.residual = v.vel_mps.tail<2>();
  obs.h = v.jacobian.bottomRows<2>();
  obs.r(0, 0) = lateral_std_mps * lateral_std_mps;
  obs.r(1, 1) = vertical_std_mps * vertical_std_mps;
  return obs;
}

}  // namespace navfuse::filter

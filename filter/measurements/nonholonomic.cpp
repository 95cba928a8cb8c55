#include "filter/measurements/nonholonomic.hpp"

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

Observation nonholonomic_observation(const StateView& s, const Eigen::Vector3d& lever_arm_m,
                                     const Eigen::Vector3d& lever_arm_std_m, double lateral_std_mps,
                                     double vertical_std_mps) {
  const BodyVelocityModel v = body_velocity_at(s, lever_arm_m, true);
  Observation obs(2);
  obs.residual = v.vel_mps.tail<2>();
  obs.h = v.jacobian.bottomRows<2>();
  obs.r(0, 0) = lateral_std_mps * lateral_std_mps;
  obs.r(1, 1) = vertical_std_mps * vertical_std_mps;
  if (!lever_arm_std_m.isZero(0.0)) {
    const Eigen::Vector3d w_eb = s.rate_b_rps - s.c_nb.transpose() * s.earth.earth_rate_ned_rps;
    const Eigen::Matrix<double, 2, 3> j = rot::skew(w_eb).bottomRows<2>();
    obs.r += j * lever_arm_std_m.cwiseAbs2().asDiagonal() * j.transpose();
  }
  return obs;
}

}  // namespace navfuse::filter

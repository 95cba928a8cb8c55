#include "filter/measurements/gravity_vector.hpp"

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

Eigen::Vector3d gravity_specific_force_mps2(const StateView& s) {
  const Eigen::Vector3d at_rest = -(s.c_nb.transpose() * s.earth.gravity_ned_mps2);
  return at_rest + s.x.accel_scale.cwiseProduct(at_rest) + s.x.accel_bias_mps2;
}

Observation gravity_vector_observation(const StateView& s, const Eigen::Vector3d& mean_raw_force_b_mps2,
                                       double std_mps2) {
  Observation obs(3);
  obs.residual = gravity_specific_force_mps2(s) - mean_raw_force_b_mps2;
  const Eigen::Matrix3d c_bn = s.c_nb.transpose();
  const Eigen::Vector3d at_rest = -(c_bn * s.earth.gravity_ned_mps2);
  // C_hat^T g - C^T g = -C^T [g x] phi (state_view.hpp), so -(C_hat^T g) moves by C^T [g x] phi,
  // through the scale as (I + diag(s_a)).
  obs.h.block<3, 3>(0, sx::kAtt) =
      (Eigen::Matrix3d::Identity() + Eigen::Matrix3d(s.x.accel_scale.asDiagonal())) * c_bn *
      rot::skew(s.earth.gravity_ned_mps2);
  obs.h.block<3, 3>(0, sx::kAccelBias).setIdentity();
  obs.h.block<3, 3>(0, sx::kAccelScale) = at_rest.asDiagonal();
  obs.r.diagonal().setConstant(std_mps2 * std_mps2);
  return obs;
}

}  // namespace navfuse::filter

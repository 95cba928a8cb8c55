#include "core/rotation/rotation.hpp"
#include "filter/measurements/external_aiding.hpp"

namespace navfuse::filter {

Observation external_heading_observation(const StateView& s, const ExternalHeading& m) {
  Observation obs(1);
  const AzimuthModel az = azimuth_of(s, Eigen::Vector3d::UnitX());
  obs.residual(0) = rot::wrap_pi(az.azimuth_rad - m.heading_rad);
  obs.h.block<1, 3>(0, sx::kAtt) = az.d_dphi;
  obs.r(0, 0) = m.std_rad * m.std_rad;
  return obs;
}

}  // namespace navfuse::filter

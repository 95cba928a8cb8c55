#include "filter/measurements/gnss_heading.hpp"

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

Eigen::Vector3d heading_baseline_b(const Eigen::Vector3d& primary, const Eigen::Vector3d& secondary) {
  const Eigen::Vector3d b = secondary - primary;
  if (b.norm() < 1e-3) return Eigen::Vector3d::UnitX();
  return b;
}

Observation gnss_heading_observation(const StateView& s, const GnssHeading& m,
                                     const Eigen::Vector3d& baseline_b) {
  Observation obs(1);
  const AzimuthModel az = azimuth_of(s, baseline_b);
  obs.residual(0) = rot::wrap_pi(az.azimuth_rad - m.heading_rad);
  obs.h.block<1, 3>(0, sx::kAtt) = az.d_dphi;
  obs.r(0, 0) = m.heading_std_rad * m.heading_std_rad;
  return obs;
}

}  // namespace navfuse::filter

#include "core/geodesy/geodesy.hpp"
#include "filter/measurements/external_aiding.hpp"

namespace navfuse::filter {

Observation external_position_observation(const StateView& s, const ExternalPosition& m) {
  Observation obs(3);
  const PointPrediction predicted = point_at(s, m.lever_arm_m);
  point_jacobian(s, m.lever_arm_m, obs);
  if (m.frame == PositionFrame::kLlh) {
    obs.residual = point_minus_llh_ned_m(s, predicted, m.value.x(), m.value.y(), m.value.z());
  } else {
    // ECEF axes: residual and Jacobian rotated from NED, d r_e = C_en d r_n.
    const Eigen::Matrix3d c_en = geo::rot_ecef_from_ned(s.x.lat_rad, s.x.lon_rad);
    obs.residual = point_ecef_m(predicted) - m.value;
    obs.h = (c_en * obs.h.topRows(3)).eval();
  }
  obs.r.diagonal() = m.std_m.array().square().matrix();
  obs.keep_rows(m.header.valid & 0b111u);
  return obs;
}

}  // namespace navfuse::filter

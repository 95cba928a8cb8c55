#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/measurements/external_aiding.hpp"

namespace navfuse::filter {

Observation external_position_observation(const StateView& s, const ExternalPosition& m) {
  Observation obs(3);
  const Eigen::Vector3d lever_n = s.c_nb * m.lever_arm_m;
  const Eigen::Vector3d offset_n = lever_n + s.x.vel_ned_mps * s.shift_s;
  obs.h.block<3, 3>(0, sx::kPos).setIdentity();
  obs.h.block<3, 3>(0, sx::kAtt) = rot::skew(lever_n);
  if (m.frame == PositionFrame::kLlh) {
    obs.residual = position_difference_ned_m(s, m.value.x(), m.value.y(), m.value.z()) + offset_n;
  } else {
    // ECEF axes: residual and Jacobian rotated from NED, d r_e = C_en d r_n.
    const geo::Llh here{s.x.lat_rad, s.x.lon_rad, s.x.height_m};
    const Eigen::Vector3d predicted = geo::ecef_from_llh(geo::llh_offset(here, offset_n));
    const Eigen::Matrix3d c_en = geo::rot_ecef_from_ned(s.x.lat_rad, s.x.lon_rad);
    obs.residual = predicted - m.value;
    obs.h = (c_en * obs.h.topRows(3)).eval();
  }
  obs.r.diagonal() = m.std_m.array().square().matrix();
  obs.keep_rows(m.header.valid & 0b111u);
  return obs;
}

}  // namespace navfuse::filter

#include "filter/measurements/magnetic_heading.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {
namespace {

// The field in a levelled frame: C(roll, pitch, 0) m_v (heading removed).
Eigen::Vector3d levelled_field(const Eigen::Quaterniond& q_nb, const Eigen::Vector3d& field_v) {
  const Eigen::Vector3d rpy = rot::rpy_from_quat(q_nb);
  return rot::dcm_from_rpy(Eigen::Vector3d(rpy.x(), rpy.y(), 0.0)) * field_v;
}

}  // namespace

Observation magnetic_heading_observation(const StateView& s, const Eigen::Vector3d& field_v,
                                         double declination_rad, double std_rad) {
  Observation obs(1);
  const AzimuthModel az = azimuth_of(s, field_v);
  obs.residual(0) = rot::wrap_pi(az.azimuth_rad - declination_rad);
  obs.h(0, sx::kAttDown) = az.d_dphi(2);  // kMagneticHeadingNeglected: heading column only
  obs.r(0, 0) = std_rad * std_rad;
  return obs;
}

double magnetic_heading_rad(const Eigen::Quaterniond& q_nb, const Eigen::Vector3d& field_v,
                            double declination_rad) {
  // C_nb = Rz(yaw) C(roll, pitch, 0) and azimuth(Rz(yaw) v) = yaw + azimuth(v).
  const Eigen::Vector3d m = levelled_field(q_nb, field_v);
  return rot::wrap_pi(declination_rad - std::atan2(m.y(), m.x()));
}

double horizontal_field(const Eigen::Quaterniond& q_nb, const Eigen::Vector3d& field_v) {
  return levelled_field(q_nb, field_v).head<2>().norm();
}

}  // namespace navfuse::filter

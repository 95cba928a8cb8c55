#include "filter/control/magnetometer_control.hpp"

#include <cmath>

#include "core/geodesy/magnetic_declination.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/alignment.hpp"
#include "filter/measurements/magnetic_heading.hpp"

namespace navfuse::filter {
namespace {

// Declination changes by well under a degree over 10 km outside the polar regions (WMM2020
// report, declination chart): recomputing it more often buys nothing.
constexpr double kDeclinationReuseRad = 10e3 / 6.371e6;

Eigen::Vector3d field_in_vehicle_frame(const FilterOptions& o, const Magnetometer& m) {
  const Eigen::Matrix3d c_vs = rot::dcm_from_rpy(o.mounting_rpy_rad);
  const Eigen::Vector3d hard_iron_s = o.magnetometer.hard_iron_gauss;
  // Hard iron is a property of the installation around the sensor: removed in the sensor frame.
  return m.frame == SensorFrame::kSensor ? Eigen::Vector3d(c_vs * (m.field_gauss - hard_iron_s))
                                         : Eigen::Vector3d(m.field_gauss - c_vs * hard_iron_s);
}

std::optional<double> declination_rad(FilterCore& c, const FilterOptions& o) {
  if (o.magnetometer.declination_rad) return o.magnetometer.declination_rad;
  if (!c.mode.position_known) return std::nullopt;
  MagnetometerState& st = c.magnetometer;
  const bool moved = std::abs(c.x.lat_rad - st.lat_rad) > kDeclinationReuseRad ||
                     std::abs(rot::wrap_pi(c.x.lon_rad - st.lon_rad)) * std::cos(c.x.lat_rad) > kDeclinationReuseRad;
  if (!st.model_declination_rad || moved) {
    st.model_declination_rad = geo::magnetic_declination_rad(c.x.lat_rad, c.x.lon_rad, c.x.height_m, c.x.time_ns);
    st.lat_rad = c.x.lat_rad;
    st.lon_rad = c.x.lon_rad;
  }
  return st.model_declination_rad;
}

}  // namespace

FuseResult fuse(FilterCore& c, const FilterOptions& o, const Magnetometer& m, double shift_s) {
  if ((m.header.valid & Magnetometer::kValidField) == 0) return FuseResult::reject(RejectReason::kInvalid);
  if (!c.mode.levelled) return FuseResult::reject(RejectReason::kNotAligned);
  const MagnetometerOptions& mo = o.magnetometer;
  const Eigen::Vector3d field_v = field_in_vehicle_frame(o, m);
  const double strength = field_v.norm();
  if (strength < mo.min_field_gauss || strength > mo.max_field_gauss ||
      horizontal_field(c.x.q_nb, field_v) < mo.min_horizontal_field_gauss) {
    return FuseResult::reject(RejectReason::kMagneticDisturbance);
  }
  const std::optional<double> declination = declination_rad(c, o);
  if (!declination) return FuseResult::reject(RejectReason::kNoDeclination);
  if (!c.mode.heading_known) {
    set_heading(c, magnetic_heading_rad(c.x.q_nb, field_v, *declination), mo.heading_std_rad);
    return FuseResult::ok();
  }
  const Observation obs = magnetic_heading_observation(c.view(shift_s), field_v, *declination, mo.heading_std_rad);
  return c.apply(o, obs, o.gate_for(GatedAid::kMagnetometer, obs.rows()));
}

}  // namespace navfuse::filter

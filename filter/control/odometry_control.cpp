#include "filter/control/odometry_control.hpp"

#include <algorithm>
#include <cmath>

#include "filter/measurements/nonholonomic.hpp"
#include "filter/measurements/wheel_speed.hpp"

namespace navfuse::filter {
namespace {

FuseResult fuse_speed(FilterCore& c, const FilterOptions& o, const std::optional<SpeedReading>& reading,
                      std::int64_t time_ns, double shift_s) {
  if (!reading) return FuseResult::reject(RejectReason::kInvalid);
  c.odometry.last_speed_mps = reading->speed_mps;
  c.odometry.last_speed_ns = time_ns;
  if (!c.navigating()) return FuseResult::reject(RejectReason::kNotAligned);
  const Observation obs = wheel_speed_observation(c.view(shift_s), *reading, o.wheel_lever_arm_m);
  return c.apply(o, obs, o.chi2_gate[0]);
}

}  // namespace

FuseResult fuse(FilterCore& c, const FilterOptions& o, const WheelSpeeds& m, double shift_s) {
  return fuse_speed(c, o, speed_from_wheels(m, o.wheel_speed_std_mps), m.header.time_ns, shift_s);
}

FuseResult fuse(FilterCore& c, const FilterOptions& o, const VehicleSpeed& m, double shift_s) {
  return fuse_speed(c, o, speed_from_vehicle(m, o.wheel_speed_std_mps), m.header.time_ns, shift_s);
}

void apply_nonholonomic(FilterCore& c, const FilterOptions& o) {
  if (!o.land_vehicle || !c.navigating() || c.stationary.stationary) return;
  // Once per cell of a fixed time grid (aligned with the covariance steps, see FilterCore).
  const std::int64_t grid_ns = std::max<std::int64_t>(1, std::llround(o.nhc_interval_s * 1e9));
  if (c.odometry.last_nhc_ns != INT64_MIN && c.x.time_ns / grid_ns == c.odometry.last_nhc_ns / grid_ns) return;
  if (c.x.vel_ned_mps.norm() < o.nhc_min_speed_mps) return;
  c.odometry.last_nhc_ns = c.x.time_ns;
  const Observation obs = nonholonomic_observation(c.view(0.0), o.nhc_lever_arm_m.value_or(o.wheel_lever_arm_m),
                                                   o.nhc_lateral_std_mps, o.nhc_vertical_std_mps);
  if (c.apply(o, obs, o.chi2_gate[1]).used) ++c.mode.nhc_updates;
}

}  // namespace navfuse::filter

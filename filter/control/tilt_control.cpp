#include "filter/control/tilt_control.hpp"

#include <cmath>

#include "filter/measurements/gravity_vector.hpp"

namespace navfuse::filter {
namespace {

bool velocity_observed(const FilterCore& c, const FilterOptions& o) {
  if (c.navigating() || c.stationary.stationary) return true;
  const std::int64_t now = c.x.time_ns;
  const auto recent = [&](std::int64_t t) { return seconds_since(now, t) <= o.gnss_timeout_s; };
  return recent(c.gnss.last_position_ns) || recent(c.gnss.last_velocity_ns) || recent(c.odometry.last_speed_ns);
}

}  // namespace

void update_accel_tilt(FilterCore& c, const FilterOptions& o, const ImuIncrement& raw) {
  if (!o.accel_tilt.enabled) return;
  TiltState& s = c.tilt;
  s.window_time_s += raw.dt_s;
  s.sum_dvel += raw.dvel_mps;
  if (s.window_time_s < o.accel_tilt.window_s) return;
  const Eigen::Vector3d mean_force = s.sum_dvel / s.window_time_s;
  s.window_time_s = 0.0;
  s.sum_dvel.setZero();
  if (!c.mode.levelled || velocity_observed(c, o)) return;

  const StateView view = c.view(0.0);
  const double deviation = std::abs(mean_force.norm() - gravity_specific_force_mps2(view).norm());
  if (deviation > o.accel_tilt.max_deviation_mps2) return;
  const Observation obs = gravity_vector_observation(view, mean_force, o.accel_tilt.std_mps2);
  if (c.apply(o, obs, o.gate_for(GatedAid::kGravity, obs.rows())).used) {
    ++s.updates;
  }
}

}  // namespace navfuse::filter

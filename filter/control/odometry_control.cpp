#include "filter/control/odometry_control.hpp"

#include <algorithm>
#include <cmath>

#include "filter/measurements/nonholonomic.hpp"
#include "filter/measurements/wheel_speed.hpp"
#include "filter/measurements/wheel_ticks.hpp"

namespace navfuse::filter {
namespace {

// Tick counts further apart than this are not differenced: the mean speed over a long interval
// says little about the speed now (a stream that paused, a logging gap).
constexpr double kMaxTickInterval_s = 2.0;

// Speed readings feed the stationary detector whether or not the filter can fuse them yet.
bool note_speed(FilterCore& c, const std::optional<SpeedReading>& reading, std::int64_t time_ns) {
  if (!reading) return false;
  c.odometry.last_speed_mps = reading->speed_mps;
  c.odometry.last_speed_ns = time_ns;
  return true;
}

FuseResult fuse_speed(FilterCore& c, const FilterOptions& o, const std::optional<SpeedReading>& reading,
                      std::int64_t time_ns, double shift_s) {
  if (!note_speed(c, reading, time_ns)) return FuseResult::reject(RejectReason::kInvalid);
  if (!c.navigating()) return FuseResult::reject(RejectReason::kNotAligned);
  const StateView view = c.view(shift_s);
  const Observation obs =
      wheel_speed_observation(view, *reading, o.wheel_lever_arm_m, forward_accel_mps2(view, c.force_b_mps2));
  return c.apply(o, obs, o.gate_for(GatedAid::kOdometry, obs.rows()));
}

// The reference slot of the stream `m` belongs to: its own, else a free one, else the oldest.
TickReference& reference_for(OdometryState& odometry, const WheelTicks& m) {
  TickReference* oldest = &odometry.tick_references.front();
  for (TickReference& r : odometry.tick_references) {
    if (r.have && r.ticks.header.stream_id == m.header.stream_id && r.ticks.channels == m.channels) return r;
  }
  for (TickReference& r : odometry.tick_references) {
    if (!r.have) return r;
    if (r.ticks.header.time_ns < oldest->ticks.header.time_ns) oldest = &r;
  }
  return *oldest;
}

}  // namespace

FuseResult fuse(FilterCore& c, const FilterOptions& o, const WheelSpeeds& m, double shift_s) {
  return fuse_speed(c, o, speed_from_wheels(m, o.wheel_speed_std_mps), m.header.time_ns, shift_s);
}

FuseResult fuse(FilterCore& c, const FilterOptions& o, const VehicleSpeed& m, double shift_s) {
  return fuse_speed(c, o, speed_from_vehicle(m, o.wheel_speed_std_mps), m.header.time_ns, shift_s);
}

FuseResult fuse(FilterCore& c, const FilterOptions& o, const WheelTicks& m, double shift_s) {
  if (!(o.wheel_m_per_tick > 0.0)) return FuseResult::reject(RejectReason::kNoScale);
  TickReference& ref = reference_for(c.odometry, m);
  const bool usable = ref.have && ref.ticks.header.stream_id == m.header.stream_id &&
                      ref.ticks.channels == m.channels &&
                      seconds_since(m.header.time_ns, ref.ticks.header.time_ns) <= kMaxTickInterval_s;
  const WheelTicks previous = ref.ticks;
  ref.ticks = m;
  ref.have = true;
  if (!usable) return FuseResult::reject(RejectReason::kNoReference);
  const std::optional<TickSpeed> speed = speed_from_ticks(previous, m, o.wheel_m_per_tick, o.wheel_speed_std_mps);
  if (!note_speed(c, speed ? std::optional<SpeedReading>(speed->reading) : std::nullopt, m.header.time_ns)) {
    return FuseResult::reject(RejectReason::kInvalid);
  }
  if (!c.navigating()) return FuseResult::reject(RejectReason::kNotAligned);
  const StateView view = c.view(shift_s);
  const Observation obs =
      wheel_tick_observation(view, *speed, o.wheel_lever_arm_m, forward_accel_mps2(view, c.force_b_mps2));
  return c.apply(o, obs, o.gate_for(GatedAid::kOdometry, obs.rows()));
}

void apply_nonholonomic(FilterCore& c, const FilterOptions& o) {
  if (!o.land_vehicle || !c.navigating() || c.stationary.stationary) return;
  // Once per cell of a fixed time grid (aligned with the covariance steps, see FilterCore).
  const std::int64_t grid_ns = std::max<std::int64_t>(1, std::llround(o.nhc_interval_s * 1e9));
  if (c.odometry.last_nhc_ns != INT64_MIN && c.x.time_ns / grid_ns == c.odometry.last_nhc_ns / grid_ns) return;
  if (c.x.vel_ned_mps.norm() < o.nhc_min_speed_mps) return;
  c.odometry.last_nhc_ns = c.x.time_ns;
  const Observation obs = nonholonomic_observation(c.view(0.0), o.nhc_point_m(),
                                                   o.nhc_lever_arm_std_m, o.nhc_lateral_std_mps,
                                                   o.nhc_vertical_std_mps);
  const FuseResult r = c.apply(o, obs, o.gate_for(GatedAid::kNhc, obs.rows()));
  r.count_innovation(c.mode.nhc_innovation);
  if (r.used) ++c.mode.nhc_updates;
}

}  // namespace navfuse::filter

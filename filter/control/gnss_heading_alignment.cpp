#include "filter/control/gnss_heading_alignment.hpp"

#include <cmath>
#include <utility>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/alignment.hpp"
#include "filter/measurements/gnss_position.hpp"
#include "filter/velocity_matching_alignment.hpp"

namespace navfuse::filter {
namespace {

// A fix newer than this is used to place the filter when the heading becomes known.
constexpr double kMaxPlacementAge_s = 1.0;
// Fixes further apart than this are not differenced: the mean velocity over a longer span says
// little about the velocity now (and a gap usually means an outage).
constexpr double kMaxFixPairSpan_s = 2.0;
// A vehicle's horizontal acceleration bound for the lag of a mean velocity (m/s^2): a car brakes
// and turns at up to ~3-4 m/s^2 in normal driving.
constexpr double kLagAccel_mps2 = 4.0;

}  // namespace

FuseResult align_heading_from_velocity(FilterCore& c, const FilterOptions& o, const AlignmentVelocity& v,
                                       std::int64_t now) {
  const Eigen::Vector2d vel_ne = v.vel_ned_mps.head<2>();
  const double speed = vel_ne.norm();
  // At rest the zero-velocity updates know the velocity better than GNSS, and a reset would
  // cut the velocity-tilt correlation that keeps the levelling honest. The velocity-matching
  // window starts again at every rest: only the motion after it carries heading information.
  if (c.stationary.stationary && speed < o.stationary_max_speed_mps) {
    restart_velocity_match(c.velocity_match, c.x.time_ns, vel_ne, v.force_integral_mps);
    return FuseResult::reject(RejectReason::kNotAligned);
  }
  c.x.vel_ned_mps = v.vel_ned_mps;
  Eigen::Matrix3d reset_cov = v.cov_m2ps2;
  reset_cov.diagonal().array() += v.state_reset_extra_var_m2ps2;
  c.ekf.reset_states(sx::kVel, reset_cov);
  c.gnss.last_velocity_ns = now;
  const double vel_var = 0.5 * (v.cov_m2ps2(0, 0) + v.cov_m2ps2(1, 1));
  std::optional<std::pair<double, double>> heading;  // yaw, std
  if (auto fit = add_velocity_match(c.velocity_match, o, c.x.time_ns, vel_ne, vel_var, v.force_integral_mps)) {
    const double yaw = rot::rpy_from_quat(c.x.q_nb).z() + fit->rotation_rad;
    heading.emplace(rot::wrap_pi(yaw), std::hypot(fit->std_rad, o.velocity_match_allowance_rad));
  }
  // Kinematic alignment (MIP §6.4): a land vehicle moving forward points along its course.
  // The course noise is the horizontal velocity std over the speed; the yaw uncertainty adds
  // an allowance for sideslip and mounting.
  const double course_std = std::sqrt(vel_var) / speed;
  if (!heading && o.course_alignment && speed >= o.kinematic_alignment_speed_mps &&
      course_std <= o.kinematic_max_course_std_rad) {
    heading.emplace(std::atan2(vel_ne.y(), vel_ne.x()), std::hypot(course_std, o.kinematic_heading_std_rad));
  }
  if (heading) {
    set_heading(c, heading->first, heading->second);
    if (c.gnss.have_fix &&
        std::abs(seconds_since(c.x.time_ns, c.gnss.latest_fix.header.time_ns)) < kMaxPlacementAge_s) {
      place_at_fix(c, o, c.gnss.latest_fix);
    }
  }
  return FuseResult::ok();
}

std::optional<AlignmentVelocity> velocity_from_fixes(const FilterOptions& o, const GnssPosition& previous,
                                                     const Eigen::Vector2d& u0, const GnssPosition& current,
                                                     const Eigen::Vector2d& u1) {
  constexpr std::uint32_t kNeeded = GnssPosition::kValidPosition | GnssPosition::kValidHeight;
  if ((previous.header.valid & kNeeded) != kNeeded || (current.header.valid & kNeeded) != kNeeded) {
    return std::nullopt;
  }
  if (previous.receiver_id != current.receiver_id) return std::nullopt;
  const double dt = seconds_since(current.header.time_ns, previous.header.time_ns);
  if (!(dt > 0.0 && dt <= kMaxFixPairSpan_s)) return std::nullopt;
  AlignmentVelocity v;
  v.vel_ned_mps = geo::ned_offset_m({previous.lat_rad, previous.lon_rad, previous.height_m},
                                    {current.lat_rad, current.lon_rad, current.height_m}) / dt;
  v.cov_m2ps2 = (gnss_position_cov_m2(previous, o.gnss_position_std_scale_for(previous.fix)) +
                 gnss_position_cov_m2(current, o.gnss_position_std_scale_for(current.fix))) /
                (dt * dt);
  if (!v.vel_ned_mps.allFinite() || !v.cov_m2ps2.allFinite()) return std::nullopt;
  // The mean of u over the interval, trapezoidal: exact for a force integral linear in time.
  v.force_integral_mps = 0.5 * (u0 + u1);
  const double lag_mps = kLagAccel_mps2 * 0.5 * dt;
  v.state_reset_extra_var_m2ps2 = lag_mps * lag_mps;
  return v;
}

}  // namespace navfuse::filter

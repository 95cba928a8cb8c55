#include "filter/control/gnss_control.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "core/rotation/rotation.hpp"
#include "filter/alignment.hpp"
#include "filter/control/baseline_check.hpp"
#include "filter/control/gnss_jump_check.hpp"
#include "filter/control/gnss_heading_alignment.hpp"
#include "filter/measurements/gnss_heading.hpp"
#include "filter/measurements/gnss_position.hpp"
#include "filter/measurements/gnss_velocity.hpp"

namespace navfuse::filter {
namespace {

bool has_position_fix(GnssFixType fix) {
  return fix != GnssFixType::kNone && fix != GnssFixType::kTimeOnly &&
         fix != GnssFixType::kDeadReckoning;
}

// A receiver whose last velocity is older than this reports none: align from its fixes instead.
constexpr double kReceiverVelocityAge_s = 1.0;

// Tracks a run of rejections; true when it has lasted long enough to re-anchor.
bool sustained_rejection(std::int64_t now, std::int64_t& reject_since, std::int64_t last_accepted,
                         double recovery_s) {
  if (reject_since == INT64_MIN) reject_since = now;
  return seconds_since(now, reject_since) >= recovery_s &&
         seconds_since(now, last_accepted) >= recovery_s;
}

// The speed between two fixes is the speed evidence of stationary detection and levelling
// (stationary_control.hpp) when it is precise enough to tell rest from motion: RTK fixes (2 cm
// at 4 Hz: ~0.1 m/s), not float or single-point ones, whose scatter would read as motion and
// keep a quiet IMU from its zero-velocity updates.
void record_speed_from_fixes(FilterCore& c, const FilterOptions& o, const AlignmentVelocity& v, std::int64_t now) {
  const double std_mps = std::sqrt(std::max(0.0, 0.5 * (v.cov_m2ps2(0, 0) + v.cov_m2ps2(1, 1))));
  if (!(std_mps < 0.5 * o.stationary_max_speed_mps)) return;
  c.gnss.last_speed_mps = v.vel_ned_mps.head<2>().norm();
  c.gnss.last_speed_ns = now;
}

// Both adaptations, then the gated update. R first (measurement_noise_adaptation.hpp): the process
// noise then sees the innovations against the noise the update will use, so an optimistic
// receiver is not mistaken for an overconfident filter. The pending covariance propagation is
// flushed first: both judge the residuals against the P the update will use.
FuseResult adapt_and_apply(FilterCore& c, const FilterOptions& o, GatedAid aid, NoiseScaleWindow& noise,
                           InnovationWindow& innovations, Observation& obs, std::int64_t now) {
  const double gate = o.gate_for(aid, obs.rows());
  c.flush_covariance(o);
  obs.r *= update_noise_scale(noise, c.ekf, obs, o.adaptation, gate);
  adapt_to_innovation(c, o, innovations, obs, now);
  return c.apply(o, obs, gate);
}

}  // namespace

FuseResult fuse(FilterCore& c, const FilterOptions& o, const GnssPosition& m,
                              double shift_s) {
  if (!has_position_fix(m.fix)) return FuseResult::reject(RejectReason::kNoFix);
  if ((m.header.valid & GnssPosition::kValidPosition) == 0) return FuseResult::reject(RejectReason::kInvalid);
  const std::int64_t now = m.header.time_ns;
  c.gnss.latest_fix = m;
  c.gnss.have_fix = true;
  // RTK fixed after a worse solution: the correction the first fixed position used brings is the
  // step the output blends (a float solution's bias of decimetres removed at once).
  if (m.fix == GnssFixType::kRtkFixed && c.gnss.last_fix != GnssFixType::kRtkFixed &&
      c.gnss.last_fix != GnssFixType::kNone) {
    c.gnss.blend_next_fixed = true;
  } else if (m.fix != GnssFixType::kRtkFixed) {
    c.gnss.blend_next_fixed = false;
  }
  c.gnss.last_fix = m.fix;
  // This fix and the previous one of its receiver, with the velocity-matching force integral at
  // each, for receivers that report no velocity.
  std::optional<GnssControlState::PairedFix> previous;
  if (m.receiver_id == 0) {
    previous = std::exchange(c.gnss.previous_primary_fix, GnssControlState::PairedFix{m, c.velocity_match.force_integral_mps});
  }
  // A receiver that reports no velocity: the mean velocity between its consecutive fixes.
  std::optional<AlignmentVelocity> from_fixes;
  if (previous && seconds_since(now, c.gnss.last_receiver_velocity_ns) > kReceiverVelocityAge_s) {
    from_fixes = velocity_from_fixes(o, previous->fix, previous->force_integral_mps, m, c.velocity_match.force_integral_mps);
    if (from_fixes) record_speed_from_fixes(c, o, *from_fixes, now);
  }
  if (!c.mode.levelled) return FuseResult::reject(RejectReason::kNotAligned);
  if (!c.mode.heading_known || !c.mode.position_known) {
    // The first fix places the filter. Without a heading the lever arm cannot be resolved and
    // any velocity error is unmodelled: hold the position at the fix (inflated by the lever arm)
    // instead of filtering.
    place_at_fix(c, o, m);
    c.gnss.last_position_ns = now;
    if (!c.mode.heading_known && from_fixes) align_heading_from_velocity(c, o, *from_fixes, now);
    return FuseResult::ok();
  }

  const NavState before = c.x;  // for the jump-free output (output_blend.hpp)
  Observation obs = gnss_position_observation(
      c.view(shift_s), m, antenna_of_receiver(c.x, o.gnss_secondary_lever_arm_m, m.receiver_id));
  const double std_scale = o.gnss_position_std_scale_for(m.fix);
  obs.r *= std_scale * std_scale;
  // A step away from the inertial track (gnss_jump_check.hpp): rejected before either adaptation
  // can take it for a filter that drifted. Primary receiver only: its fixes are compared in turn.
  const JumpVerdict jump = m.receiver_id == 0 ? check_gnss_jump(c, o, m, obs) : JumpVerdict::kClean;
  if (jump == JumpVerdict::kDisplaced) {
    obs.r *= c.adaptation.position_noise.scale;
    note_processed_fix(c, m, obs);
    return FuseResult::reject(RejectReason::kGnssJump);
  }
  const FuseResult r =
      adapt_and_apply(c, o, GatedAid::kGnssPosition, c.adaptation.position_noise, c.adaptation.position, obs, now);
  // What the next fix's step is measured from: this fix against the state after it (updated,
  // gated or re-anchored below), with the R it was held to.
  const auto remember_fix = [&] {
    if (m.receiver_id != 0) return;
    Observation post = gnss_position_observation(c.view(shift_s), m, antenna_of_receiver(c.x, {}, 0));
    post.r = obs.r;
    note_processed_fix(c, m, post);
  };
  if (r.used) {
    if (c.gnss.blend_next_fixed) {
      blend_position_jump(c, o, before);
      c.gnss.blend_next_fixed = false;
    }
    c.gnss.last_position_ns = now;
    c.gnss.position_reject_since_ns = INT64_MIN;
    c.mode.position_known = true;
    c.mode.last_absolute_position_ns = now;
    remember_fix();
    return r;
  }
  if (r.reason == RejectReason::kChi2Gate &&
      (jump == JumpVerdict::kHeldTooLong ||
       sustained_rejection(now, c.gnss.position_reject_since_ns, c.gnss.last_position_ns, o.gnss_recovery_s))) {
    place_at_fix(c, o, m);
    blend_position_jump(c, o, before);
    // The velocity that carried the filter away is suspect too: widen it so the next velocity
    // fixes pull it in.
    c.ekf.reset_states(sx::kVel, 3, 1.0);
    c.gnss.last_position_ns = now;
    c.gnss.position_reject_since_ns = INT64_MIN;
    ++c.mode.gnss_recoveries;
    remember_fix();
    return FuseResult::ok();
  }
  remember_fix();
  return r;
}

FuseResult fuse(FilterCore& c, const FilterOptions& o, const GnssVelocity& m,
                              double shift_s) {
  if (!has_position_fix(m.fix)) return FuseResult::reject(RejectReason::kNoFix);
  if ((m.header.valid & GnssVelocity::kValidVelocity) == 0) return FuseResult::reject(RejectReason::kInvalid);
  const std::int64_t now = m.header.time_ns;
  const double speed = m.vel_ned_mps.head<2>().norm();
  c.gnss.last_speed_mps = speed;
  c.gnss.last_speed_ns = now;
  c.gnss.last_receiver_velocity_ns = now;
  if (!c.mode.levelled) return FuseResult::reject(RejectReason::kNotAligned);
  const Eigen::Matrix3d cov = o.gnss_velocity_std_scale * o.gnss_velocity_std_scale *
                              ((m.header.valid & GnssVelocity::kValidCovariance) != 0
                                   ? m.cov_ned_m2ps2
                                   : Eigen::Matrix3d(Eigen::Vector3d(0.01, 0.01, 0.04).asDiagonal()));
  const double course_std = std::sqrt(0.5 * (cov(0, 0) + cov(1, 1))) / speed;
  // A baseline found wrong: the heading it gave is not known after all; re-align from the course
  // below, at this epoch (the vehicle is moving fast enough, or it would not have been checked).
  if (c.mode.heading_known && check_baseline(c, o, m, course_std)) c.mode.heading_known = false;
  if (!c.mode.heading_known) {
    AlignmentVelocity v;
    v.vel_ned_mps = m.vel_ned_mps;
    v.cov_m2ps2 = cov;
    return align_heading_from_velocity(c, o, v, now);
  }

  Observation obs = gnss_velocity_observation(
      c.view(shift_s), m, antenna_of_receiver(c.x, o.gnss_secondary_lever_arm_m, m.receiver_id));
  obs.r = cov;
  const FuseResult r =
      adapt_and_apply(c, o, GatedAid::kGnssVelocity, c.adaptation.velocity_noise, c.adaptation.velocity, obs, now);
  if (r.used) {
    c.gnss.last_velocity_ns = now;
    c.gnss.velocity_reject_since_ns = INT64_MIN;
    return r;
  }
  if (r.reason == RejectReason::kChi2Gate &&
      sustained_rejection(now, c.gnss.velocity_reject_since_ns, c.gnss.last_velocity_ns,
                          o.gnss_recovery_s)) {
    c.x.vel_ned_mps = m.vel_ned_mps;
    c.ekf.reset_states(sx::kVel, cov);
    c.gnss.last_velocity_ns = now;
    c.gnss.velocity_reject_since_ns = INT64_MIN;
    ++c.mode.gnss_recoveries;
    return FuseResult::ok();
  }
  return r;
}

FuseResult fuse(FilterCore& c, const FilterOptions& o, const GnssHeading& m,
                             double shift_s) {
  if ((m.header.valid & GnssHeading::kValidHeading) == 0) return FuseResult::reject(RejectReason::kInvalid);
  if (!c.mode.levelled) return FuseResult::reject(RejectReason::kNotAligned);
  if (c.gnss.baseline.offset_detected) return FuseResult::reject(RejectReason::kBaselineMismatch);
  const Eigen::Vector3d baseline = heading_baseline_b(o.gnss_lever_arm_m, o.gnss_secondary_lever_arm_m);
  note_antenna_yaw(c, m.header.time_ns, rot::wrap_pi(m.heading_rad - std::atan2(baseline.y(), baseline.x())));
  if (!c.mode.heading_known) {
    set_heading(c, m.heading_rad - std::atan2(baseline.y(), baseline.x()), m.heading_std_rad);
    c.gnss.last_heading_ns = m.header.time_ns;
    return FuseResult::ok();
  }
  const Observation obs = gnss_heading_observation(c.view(shift_s), m, baseline);
  const FuseResult r = c.apply(o, obs, o.gate_for(GatedAid::kGnssHeading, obs.rows()));
  if (r.used) c.gnss.last_heading_ns = m.header.time_ns;
  return r;
}

}  // namespace navfuse::filter

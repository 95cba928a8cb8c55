#include "filter/control/gnss_jump_check.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "filter/filter_core.hpp"

namespace navfuse::filter {
namespace {

// The median of chi-square(m) / m for m = 1, 2, 3: what the median of the steps' normalised
// squares is when R and P are right.
double chi2_median_per_dim(int rows) {
  constexpr double kMedian[3] = {0.4549, 1.3863 / 2.0, 2.3660 / 3.0};
  return kMedian[std::clamp(rows, 1, 3) - 1];
}

double recent_median(const GnssJumpState& j) {
  if (j.recent_count == 0) return 0.0;
  std::array<double, GnssJumpState::kWindow> v = j.recent_step;
  const auto mid = v.begin() + (j.recent_count - 1) / 2;  // the lower median
  std::nth_element(v.begin(), mid, v.begin() + j.recent_count);
  return *mid;
}

void push_step(GnssJumpState& j, double per_dim) {
  j.recent_step[static_cast<std::size_t>(j.recent_next)] = per_dim;
  j.recent_next = (j.recent_next + 1) % GnssJumpState::kWindow;
  j.recent_count = std::min(j.recent_count + 1, GnssJumpState::kWindow);
}

Eigen::Vector3d padded(const Observation::Residual& d) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  out.head(d.size()) = d;
  return out;
}

// d^T S^-1 d; infinity when S is not positive definite. Fixed-capacity types: no heap per fix.
double step_nis(const Observation::Residual& d, const Observation::Noise& s) {
  const Eigen::LLT<Observation::Noise> llt(s);
  if (llt.info() != Eigen::Success) return INFINITY;
  const Observation::Residual x = llt.solve(d);
  return d.dot(x);
}

// The step from the previous fix to this one, over the rows both have (a fix without height has
// two), with the covariance it is judged by and the stream's own scale.
struct Step {
  Observation::Residual d;
  Observation::Noise s;
  double scale = 1.0;   // the recent ordinary steps' median over chi-square's, >= 1
  bool flagged = false;  // beyond gates.gnss_jump (after the scale) and gnss.jump_min_m
  int rows() const { return static_cast<int>(d.size()); }
  // v^T S^-1 v / scale over the step's rows.
  double nis_of(const Eigen::Vector3d& v, const Observation::Noise& cov) const {
    const Observation::Residual head = v.head(rows());
    return step_nis(head, cov) / scale;
  }
};

// Measures the step of `probe` (the fix with the R its update would use) from the previous fix
// `dt_s` earlier; an ordinary one joins the window that sets the scale. The scale (a median) is
// taken only where it can matter: for a step the gate would flag at scale 1, or while displaced.
Step measure_step(GnssJumpState& j, const FilterOptions& o, const Ekf& ekf, const Observation& probe, double dt_s) {
  Step st;
  const int rows = std::min<int>(probe.rows(), static_cast<int>(j.previous_post_fit.size()));
  st.d = probe.residual.head(rows) - j.corrections_ned_m.head(rows) - j.previous_post_fit.head(rows);
  st.s = probe.r.topLeftCorner(rows, rows) + j.previous_r.topLeftCorner(rows, rows) +
         dt_s * dt_s * ekf.p.block(sx::kVel, sx::kVel, rows, rows);
  const double per_dim = step_nis(st.d, st.s) / rows;
  if (per_dim * rows > o.gnss_jump_gate || j.displaced()) {
    st.scale = std::max(1.0, recent_median(j) / chi2_median_per_dim(rows));
  }
  st.flagged = j.recent_count >= GnssJumpState::kMinSamples && per_dim * rows / st.scale > o.gnss_jump_gate &&
               st.d.norm() >= o.gnss_jump_min_m;
  if (!st.flagged && std::isfinite(per_dim)) push_step(j, per_dim);
  return st;
}

// While displaced: the fixes since the step must keep their offset against the inertial track.
// Back to where the stream was (what it moved since the step undone to within the gate) ends the
// displacement: the receiver came back. A stream that keeps moving against the track (the sum of
// the steps since beyond the gate, with the velocity's uncertainty over the whole time) is not a
// step but a filter drifting off it, which is the adaptation's to repair. Another step that is
// neither is held one fix: a glitch is undone by the next one and counts for nothing.
JumpVerdict follow_displacement(GnssJumpState& j, const FilterOptions& o, const Ekf& ekf, const Observation& probe,
                                const Step& st, std::int64_t now) {
  const Eigen::Vector3d d = padded(st.d);
  if (j.pending_ned_m) {
    const bool undone = st.nis_of(*j.pending_ned_m + d, st.s) <= o.gnss_jump_gate;
    if (!undone) j.drift_ned_m += *j.pending_ned_m + d;
    j.pending_ned_m.reset();
  } else if (st.flagged && st.nis_of(j.displacement_ned_m + j.drift_ned_m + d, st.s) > o.gnss_jump_gate) {
    j.pending_ned_m = d;
    return JumpVerdict::kDisplaced;
  } else {
    j.drift_ned_m += d;
  }
  const int rows = st.rows();
  const double since_s = seconds_since(now, j.displaced_since_ns);
  const Observation::Noise s_drift = probe.r.topLeftCorner(rows, rows) + j.previous_r.topLeftCorner(rows, rows) +
                                     since_s * since_s * ekf.p.block(sx::kVel, sx::kVel, rows, rows);
  if (st.nis_of(j.displacement_ned_m + j.drift_ned_m, st.s) <= o.gnss_jump_gate ||
      st.nis_of(j.drift_ned_m, s_drift) > o.gnss_jump_gate) {
    j.displaced_since_ns = INT64_MIN;
    return JumpVerdict::kClean;
  }
  return JumpVerdict::kDisplaced;
}

}  // namespace

JumpVerdict check_gnss_jump(FilterCore& c, const FilterOptions& o, const GnssPosition& m, const Observation& obs) {
  GnssJumpState& j = c.gnss.jump;
  if (o.gnss_jump_hold_s <= 0.0 || obs.rows() == 0) return JumpVerdict::kClean;
  const std::int64_t now = m.header.time_ns;
  const double dt_s = j.have_previous ? static_cast<double>(now - j.previous_ns) * 1e-9 : INFINITY;
  const bool comparable = j.have_previous && m.fix == j.previous_fix && dt_s > 0.0 &&
                          dt_s <= GnssJumpState::kMaxInterval_s;
  if (!comparable) {  // a new solution, or the first fix in a while: nothing to compare with
    j.displaced_since_ns = INT64_MIN;
    return JumpVerdict::kClean;
  }
  const bool held_too_long = j.displaced() && seconds_since(now, j.displaced_since_ns) > o.gnss_jump_hold_s;
  if (held_too_long) j.displaced_since_ns = INT64_MIN;

  c.flush_covariance(o);
  Observation probe = obs;  // with the R its update would be held to
  probe.r *= c.adaptation.position_noise.scale;
  const Step st = measure_step(j, o, c.ekf, probe, dt_s);
  // Nothing in force and no step: the common case, decided without the fix's own innovation.
  if (!j.displaced() && !held_too_long && !st.flagged) return JumpVerdict::kClean;
  if (c.ekf.innovation_moments(probe).nis <= o.gate_for(GatedAid::kGnssPosition, probe.rows())) {
    j.displaced_since_ns = INT64_MIN;  // the fix agrees with the filter: nothing is displaced
    return JumpVerdict::kClean;
  }
  if (held_too_long) return JumpVerdict::kHeldTooLong;
  if (j.displaced()) return follow_displacement(j, o, c.ekf, probe, st, now);
  if (!st.flagged) return JumpVerdict::kClean;
  j.displaced_since_ns = now;
  j.displacement_ned_m = padded(st.d);
  j.drift_ned_m.setZero();
  j.pending_ned_m.reset();
  return JumpVerdict::kDisplaced;
}

void note_processed_fix(FilterCore& c, const GnssPosition& m, const Observation& post_fit) {
  GnssJumpState& j = c.gnss.jump;
  j.have_previous = true;
  j.previous_ns = m.header.time_ns;
  j.previous_fix = m.fix;
  j.previous_post_fit = post_fit.residual;
  j.previous_r = post_fit.r;
  j.corrections_ned_m.setZero();
}

}  // namespace navfuse::filter

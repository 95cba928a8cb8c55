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

}  // namespace

JumpVerdict check_gnss_jump(FilterCore& c, const FilterOptions& o, const GnssPosition& m, const Observation& obs) {
  GnssJumpState& j = c.gnss.jump;
  if (o.gnss_jump_hold_s <= 0.0 || obs.rows() == 0) return JumpVerdict::kClean;
  const std::int64_t now = m.header.time_ns;
  const double dt_s = j.have_previous ? static_cast<double>(now - j.previous_ns) * 1e-9 : INFINITY;
  const bool comparable = j.have_previous && m.fix == j.previous_fix && dt_s > 0.0 &&
                          dt_s <= GnssJumpState::kMaxInterval_s;
  const bool held_too_long = j.displaced() && seconds_since(now, j.displaced_since_ns) > o.gnss_jump_hold_s;
  if (!comparable || held_too_long) j.displaced_since_ns = INT64_MIN;  // a new solution, or held long enough

  // The fix against the filter, with the R its update would be held to.
  c.flush_covariance(o);
  Observation probe = obs;
  probe.r *= c.adaptation.position_noise.scale;
  const bool fits_filter = c.ekf.innovation_moments(probe).nis <= o.gate_for(GatedAid::kGnssPosition, probe.rows());

  // The step from the previous fix, over the rows both have (a fix without height has two), its
  // normalised square against the stream's own scale.
  bool step = false;
  Observation::Residual d;
  Observation::Noise s;
  double scale = 1.0;
  if (comparable) {
    const int rows = std::min<int>(probe.rows(), static_cast<int>(j.previous_post_fit.size()));
    d = probe.residual.head(rows) - j.corrections_ned_m.head(rows) - j.previous_post_fit.head(rows);
    s = probe.r.topLeftCorner(rows, rows) + j.previous_r.topLeftCorner(rows, rows) +
        dt_s * dt_s * c.ekf.p.block(sx::kVel, sx::kVel, rows, rows);
    const double per_dim = step_nis(d, s) / rows;
    scale = std::max(1.0, recent_median(j) / chi2_median_per_dim(rows));
    step = j.recent_count >= GnssJumpState::kMinSamples && per_dim * rows / scale > o.gnss_jump_gate &&
           d.norm() >= o.gnss_jump_min_m;
    if (!step && std::isfinite(per_dim)) push_step(j, per_dim);
  }

  if (fits_filter || !comparable) {
    j.displaced_since_ns = INT64_MIN;
    return JumpVerdict::kClean;
  }
  if (held_too_long) return JumpVerdict::kHeldTooLong;
  const Eigen::Vector3d d3 = padded(d);
  const int rows = static_cast<int>(d.size());
  if (!j.displaced()) {
    if (!step) return JumpVerdict::kClean;
    j.displaced_since_ns = now;
    j.displacement_ned_m = d3;
    j.drift_ned_m.setZero();
    j.pending_ned_m.reset();
    return JumpVerdict::kDisplaced;
  }
  // Displaced: the fixes since the step must keep their offset against the inertial track. Back
  // to where the stream was (what it moved since the step undone to within the gate) ends the
  // displacement: the receiver came back. A stream that keeps moving against the track (the sum
  // of the steps since beyond the gate, with the velocity's uncertainty over the whole time) is
  // not a step but a filter drifting off it, which is the adaptation's to repair. Another step
  // that is neither is held one fix: a glitch is undone by the next one and counts for nothing.
  const auto nis_of = [&](const Eigen::Vector3d& v, const Observation::Noise& cov) {
    const Observation::Residual head = v.head(rows);
    return step_nis(head, cov) / scale;
  };
  if (j.pending_ned_m) {
    const bool undone = nis_of(*j.pending_ned_m + d3, s) <= o.gnss_jump_gate;
    if (!undone) j.drift_ned_m += *j.pending_ned_m + d3;
    j.pending_ned_m.reset();
  } else if (step && nis_of(j.displacement_ned_m + j.drift_ned_m + d3, s) > o.gnss_jump_gate) {
    j.pending_ned_m = d3;
    return JumpVerdict::kDisplaced;
  } else {
    j.drift_ned_m += d3;
  }
  const double since_s = seconds_since(now, j.displaced_since_ns);
  const Observation::Noise s_drift = probe.r.topLeftCorner(rows, rows) + j.previous_r.topLeftCorner(rows, rows) +
                                     since_s * since_s * c.ekf.p.block(sx::kVel, sx::kVel, rows, rows);
  if (nis_of(j.displacement_ned_m + j.drift_ned_m, s) <= o.gnss_jump_gate ||
      nis_of(j.drift_ned_m, s_drift) > o.gnss_jump_gate) {
    j.displaced_since_ns = INT64_MIN;
    return JumpVerdict::kClean;
  }
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

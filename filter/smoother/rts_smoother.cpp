#include "filter/smoother/rts_smoother.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include "core/rotation/rotation.hpp"
#include "filter/solution.hpp"

namespace navfuse::filter {
namespace {

// The covariance blocks the outputs and the NEES use, kept per node.
struct Blocks {
  static constexpr std::array<int, 5> kFirst{sx::kPos, sx::kVel, sx::kAtt, sx::kGyroBias, sx::kAccelBias};
  std::array<Eigen::Matrix3d, 5> b;

  static Blocks of(const Covariance& p) {
    Blocks out;
    for (std::size_t i = 0; i < kFirst.size(); ++i) out.b[i] = p.block<3, 3>(kFirst[i], kFirst[i]);
    return out;
  }
  // (1 - f) a + f c, as a full covariance with zeros outside the blocks.
  static Covariance blend(const Blocks& a, const Blocks& c, double f) {
    Covariance p = Covariance::Zero();
    for (std::size_t i = 0; i < kFirst.size(); ++i) p.block<3, 3>(kFirst[i], kFirst[i]) = (1.0 - f) * a.b[i] + f * c.b[i];
    return p;
  }
};

// One smoothed covariance interval: records (start, end) and the corrections at both ends.
struct Interval {
  std::size_t start_record = 0;  // kIntervalStart
  std::size_t end_record = 0;    // kPropagation
  std::int64_t start_ns = 0, end_ns = 0;
  StateVector d_start = StateVector::Zero();  // applied to x+ at the start
  StateVector d_end = StateVector::Zero();    // applied to x- at the end
  Blocks p_start, p_end;
};

// C = P+ Phi^T (P-)^-1 over the states with prior variance; false when P- cannot be inverted.
bool rts_gain(const ForwardRecordEntry& start, const ForwardRecordEntry& prior, Eigen::MatrixXd& gain) {
  const int n = prior.n;
  std::vector<int> s;
  for (int i = 0; i < n; ++i) {
    if (prior.p(i, i) > 0.0) s.push_back(i);
  }
  const int m = static_cast<int>(s.size());
  // Scaled to unit diagonal before factoring: variances span ~1e-18 (gyro bias) to ~1e6.
  Eigen::VectorXd scale(m);
  Eigen::MatrixXd pn(m, m);
  for (int a = 0; a < m; ++a) scale(a) = std::sqrt(prior.p(s[a], s[a]));
  for (int a = 0; a < m; ++a) {
    for (int c = 0; c < m; ++c) pn(a, c) = prior.p(s[a], s[c]) / (scale(a) * scale(c));
  }
  // B = Phi P+ restricted to rows S; C^T = (P-)^-1 B.
  const Eigen::MatrixXd b = prior.phi.topLeftCorner(n, n) * start.p.topLeftCorner(n, n);
  Eigen::MatrixXd bs(m, n);
  for (int a = 0; a < m; ++a) bs.row(a) = b.row(s[a]) / scale(a);
  Eigen::LDLT<Eigen::MatrixXd> ldlt(pn);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return false;
  Eigen::MatrixXd ct = ldlt.solve(bs);
  if (!ct.allFinite()) return false;
  gain.setZero(n, n);
  for (int a = 0; a < m; ++a) gain.col(s[a]) = ct.row(a).transpose() / scale(a);
  return true;
}

// The backward pass: smoothed corrections per interval, in time order (a deque, filled from the
// front: no reallocation doubling the peak memory of a long log).
std::deque<Interval> backward_pass(ForwardRecorder& rec, SmootherStats& stats, const std::function<void(double)>& progress) {
  enum class Have { kNothing, kSmoothed, kPrior };
  Have have = Have::kNothing;
  NavState xs;                          // smoothed state at the newest node seen
  Covariance ps = Covariance::Zero();  // and its covariance
  ForwardRecordEntry prior, start;      // kPropagation at the end of the interval, kIntervalStart
  std::size_t prior_record = 0;
  StateVector e_end = StateVector::Zero();
  Covariance ps_end = Covariance::Zero();
  std::deque<Interval> out;
  bool segment_open = false;
  Eigen::MatrixXd gain;
  // A re-inflation after an outage (the first fixes after it were gated: the filter's covariance
  // had grown too little over the outage) says the covariance was too small, not that the error
  // grew by D at that instant: through it the gain is I, the error the same on both sides. With
  // the recorded Phi = D the gain D^-1 kept the fix that ended the outage from correcting the
  // outage's end (parking_drive, 15 s outages every 45 s: end-of-outage error 0.170 m smoothed,
  // 0.729 m forward). Re-inflations while fixes arrive keep D^-1: there the jump is the
  // installation's (a wrong mounting), and carrying it back smoothed metres of error into a drive
  // the forward filter had to 4 cm (SmootherScenario.NoWorseThanForwardOnAWrongInstallation).
  // Carrying D back over the whole outage as a covariance scale instead made the outage worse
  // (2.1 m RMS on parking_drive): the NHC updates inside it meet a P they never saw.
  const std::size_t total = rec.size();
  for (std::size_t i = total; i-- > 0;) {
    if (progress && (i & 0xFFFF) == 0) progress(0.5 * static_cast<double>(total - i) / static_cast<double>(total));
    switch (rec.type(i)) {
      case RecordType::kImu:
      case RecordType::kUpdate:
        continue;
      case RecordType::kRestart:
      case RecordType::kBreak:
        have = Have::kNothing;
        segment_open = false;
        continue;
      case RecordType::kClose:
        if (!rec.read(i, start)) return out;
        xs = start.x;
        ps = start.p;
        have = Have::kSmoothed;
        continue;
      case RecordType::kPropagation:
        if (!rec.read(i, prior)) return out;
        prior_record = i;
        if (have != Have::kSmoothed) {  // the segment's last node: no update after it
          xs = prior.x;
          ps = prior.p;
        }
        e_end = state_difference(prior.x, xs);
        ps_end = ps;
        have = Have::kPrior;
        continue;
      case RecordType::kIntervalStart:
        if (!rec.read(i, start)) return out;
        if (!start.navigating) {
          // Before position and heading are known the prior is not a distribution around the
          // truth (heading relative, position not placed, P ~ 1e6 m^2): not smoothed, and the
          // first navigating node starts a segment of its own.
          have = Have::kNothing;
          segment_open = false;
          continue;
        }
        if (have == Have::kPrior) {
          const bool pass_through = prior.time_ns == start.time_ns && start.inflation_after_outage;
          if (pass_through || rts_gain(start, prior, gain)) {
            const int n = prior.n;
            Interval iv;
            iv.start_record = i;
            iv.end_record = prior_record;
            iv.start_ns = start.time_ns;
            iv.end_ns = prior.time_ns;
            if (pass_through) {
              iv.d_start = e_end;
              ps = ps_end;
            } else {
              iv.d_start.head(n) = gain * e_end.head(n);
              ps = start.p;
              ps.topLeftCorner(n, n) += gain * (ps_end - prior.p).topLeftCorner(n, n) * gain.transpose();
              ps = (0.5 * (ps + ps.transpose())).eval();
            }
            iv.d_end = e_end;
            xs = start.x;
            inject_error(xs, iv.d_start);
            iv.p_start = Blocks::of(ps);
            iv.p_end = Blocks::of(ps_end);
            out.push_front(iv);
            ++stats.intervals;
            if (!segment_open) ++stats.segments;
            segment_open = true;
            have = Have::kSmoothed;
            continue;
          }
          ++stats.singular;
          segment_open = false;
        }
        // Nothing after this node in its segment (or no usable gain): it keeps the filtered state.
        xs = start.x;
        ps = start.p;
        have = Have::kSmoothed;
        continue;
    }
  }
  return out;
}

}  // namespace

SmootherStats smooth(ForwardRecorder& rec, const std::function<void(const SmoothedSample&)>& on_sample,
                     const std::function<void(double)>& progress) {
  SmootherStats stats;
  const std::deque<Interval> intervals = backward_pass(rec, stats, progress);
  if (!rec.error().empty()) {
    stats.error = rec.error();
    return stats;
  }
  // Forward over the IMU samples: each inside an interval gets its blended correction.
  ForwardRecordEntry e;
  std::size_t j = 0;
  const std::size_t total = rec.size();
  for (std::size_t i = 0; i < total; ++i) {
    if (progress && (i & 0xFFFF) == 0) progress(0.5 + 0.5 * static_cast<double>(i) / static_cast<double>(total));
    if (rec.type(i) != RecordType::kImu) continue;
    ++stats.imu_samples;
    while (j < intervals.size() && intervals[j].end_record < i) ++j;
    if (j == intervals.size() || intervals[j].start_record > i) continue;
    const Interval& iv = intervals[j];
    if (!rec.read(i, e)) break;
    const double span = static_cast<double>(iv.end_ns - iv.start_ns);
    const double f = span > 0.0 ? std::clamp(static_cast<double>(e.time_ns - iv.start_ns) / span, 0.0, 1.0) : 1.0;
    NavState x = e.x;
    inject_error(x, (1.0 - f) * iv.d_start + f * iv.d_end);
    on_sample(SmoothedSample{x, Blocks::blend(iv.p_start, iv.p_end, f), e});
    ++stats.smoothed_samples;
  }
  if (progress) progress(1.0);
  stats.error = rec.error();
  return stats;
}

NavSolution smoothed_solution(const SmoothedSample& s, const FilterOptions& o, TimeSource time_source) {
  const ForwardRecordEntry& f = s.forward;
  NavSolution out;
  out.header.time_ns = s.x.time_ns;
  out.header.time_source = time_source;
  const bool navigating = f.mode == NavMode::kNavigation || f.mode == NavMode::kDeadReckoning;
  out.mode = navigating ? NavMode::kSmoothed : f.mode;
  out.gnss_fix = f.gnss_fix;
  StateFieldInputs state;
  capture_state_fields(s.x, s.p, f.rate_b_rps, f.force_b_mps2, f.gravity_ned_mps2, rot::dcm_from_rpy(o.mounting_rpy_rad),
                       o.states, state);
  fill_state_fields(state, out);
  out.header.valid |= f.valid;
  out.status_flags = f.status_flags;
  return out;
}

}  // namespace navfuse::filter

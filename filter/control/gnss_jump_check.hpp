// GNSS position steps: a receiver that tracks a reflected signal, or fixes an ambiguity wrongly,
// moves its position by decimetres to metres from one epoch to the next while it keeps reporting
// the std devs of its fix type (Groves 2nd ed. §9.3.4 on multipath and NLOS reception; the sim's
// apps/sim/gnss_multipath.hpp). The fixes after such a step agree with each other, so the
// innovation adaptation (innovation_adaptation.hpp) reads them as a filter that drifted off a
// healthy stream, re-inflates P and follows them; the re-anchoring (gnss_control.hpp) would
// follow them after gnss.recovery_s as well.
//
// What tells the two apart is the step itself. Between consecutive fixes of one receiver and fix
// type, a fraction of a second apart, the inertial track moves the antenna with an error of
// millimetres to centimetres, so the change of the innovation from the previous fix's post-fit
// residual,
//
//   d_k = nu_k - rho_{k-1},   S_d = R_k + R_{k-1} + dt^2 P_vv,
//
// with what other updates moved the filter in between taken out, is the difference of two fixes'
// noise (plus the velocity error over dt) on a healthy stream, and the step on a displaced one. A
// filter that is merely overconfident drifts: its innovations grow over many epochs, each d_k
// small. It is change detection on time-differenced positions with the INS as the predictor, as
// cycle slips are found in carrier phase (Groves 2nd ed. ch. 17 on fault detection).
//
// A step (d^T S_d^-1 d above gates.gnss_jump, after the stream's own scale below) to a fix that
// fails the filter's own gate starts a displacement: from then on the fixes are rejected as
// `gnss_jump`, and neither adaptation nor the re-anchoring sees them, until a fix passes the
// filter's gate again, a step takes the stream back to where it was (the receiver came back), the
// fixes stop keeping their offset against the inertial track (they move on against it: the
// filter is drifting, not the receiver), or gnss.jump_hold_s has passed (a displacement that long
// is taken as real: the filter re-anchors to it, as after gnss.recovery_s of rejected fixes). A
// new fix type, or a gap longer than kMaxInterval_s, ends the comparison: a float-to-fixed
// transition moves the position on purpose.
//
// The statistic trusts R and P only as far as the stream's own steps bear them out: it is divided
// by the median of the recent ordinary steps' over the median chi-square(m) expects (floored at
// 1), as the measurement-noise adaptation scales R (measurement_noise_adaptation.hpp). With the
// receiver's std devs 4x optimistic and a vibrating IMU (parking_drive), R alone made every
// other fix a step: 28 % of the fixes used.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"
#include "filter/ekf.hpp"
#include "filter/filter_options.hpp"

namespace navfuse::filter {

struct FilterCore;

struct GnssJumpState {
  // Longer between fixes and the inertial track's own drift is no longer small beside a step.
  static constexpr double kMaxInterval_s = 2.0;
  // The recent steps' normalised squares whose median sets the stream's own scale (below).
  static constexpr int kWindow = 16;
  static constexpr int kMinSamples = 8;  // fewer: no step is flagged yet
  bool have_previous = false;
  std::int64_t previous_ns = 0;
  GnssFixType previous_fix = GnssFixType::kNone;
  Observation::Residual previous_post_fit;  // h(x) - z after the previous fix was processed
  Observation::Noise previous_r;            // the R it was held to
  // What the updates since then moved the position by (NED, m; FilterCore::apply adds each
  // correction): the filter's own steps, taken out of the next fix's innovation. A GNSS velocity
  // fused right after a gated fix moves the position through their correlation by decimetres
  // after an outage (the shared walk).
  Eigen::Vector3d corrections_ned_m = Eigen::Vector3d::Zero();
  // d^T S_d^-1 d / rows of the recent ordinary steps. Their median over that of chi-square(m)/m
  // is how much larger the steps run than R and P say (a receiver's optimistic std devs, a
  // vibrating IMU's velocity error); each step is judged against that, never below 1.
  std::array<double, kWindow> recent_step{};
  int recent_count = 0;
  int recent_next = 0;
  std::int64_t displaced_since_ns = INT64_MIN;  // INT64_MIN: no displacement in force
  Eigen::Vector3d displacement_ned_m = Eigen::Vector3d::Zero();  // the step that began it
  Eigen::Vector3d drift_ned_m = Eigen::Vector3d::Zero();         // the steps since
  std::optional<Eigen::Vector3d> pending_ned_m;  // a step while displaced, until the next fix says what it was
  bool displaced() const { return displaced_since_ns != INT64_MIN; }
};

enum class JumpVerdict {
  kClean,        // no displacement in force: fuse as usual
  kDisplaced,    // reject as gnss_jump
  kHeldTooLong,  // a displacement just outlived gnss.jump_hold_s: re-anchor unless the fix is taken
};

// Before the update of a primary-receiver fix. `obs` carries the fix's R as the update will use it.
JumpVerdict check_gnss_jump(FilterCore& core, const FilterOptions& o, const GnssPosition& m, const Observation& obs);

// After the fix was processed (used, gated, displaced or re-anchored): remembers its post-fit
// residual for the next comparison.
void note_processed_fix(FilterCore& core, const GnssPosition& m, const Observation& post_fit);

}  // namespace navfuse::filter

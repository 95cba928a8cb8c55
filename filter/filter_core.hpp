// The complete, copyable state of the running filter: nominal state, covariance, the integration
// memories and every control/alignment/mode variable. The Engine snapshots it for re-propagation
// of late measurements, so it holds no pointers into the Engine and no heap memory.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"
#include "filter/output_blend.hpp"
#include "filter/control/gnss_jump_check.hpp"
#include "filter/control/innovation_adaptation.hpp"
#include "filter/ekf.hpp"
#include "filter/filter_options.hpp"
#include "filter/filter_stats.hpp"
#include "filter/measurements/state_view.hpp"
#include "filter/nav_state.hpp"
#include "filter/process_model.hpp"
#include "filter/smoother/record_hook.hpp"
#include "filter/strapdown.hpp"
#include "filter/velocity_matching_alignment.hpp"

namespace navfuse::filter {

// Seconds from `earlier` to `later`; infinity when `earlier` never happened (INT64_MIN).
inline double seconds_since(std::int64_t later, std::int64_t earlier) {
  if (earlier == INT64_MIN) return 1e300;
  return static_cast<double>(later - earlier) * 1e-9;
}

// The result of offering one measurement to the filter, with its innovation when an update was
// tried (accepted or gated): what `--innovations-csv` and the innovation statistics report.
struct FuseResult {
  bool used = false;
  RejectReason reason = RejectReason::kInvalid;
  int rows = 0;       // measurement dimension of the update tried; 0: none was
  double nis = 0.0;   // r^T S^-1 r
  std::array<double, 3> residual{};        // h(x) - z, per row
  std::array<double, 3> innovation_std{};  // sqrt(diag S), per row
  static FuseResult ok() { return FuseResult{true, RejectReason::kInvalid}; }
  static FuseResult reject(RejectReason r) { return FuseResult{false, r}; }
  // Into `stats` when an update was tried (accepted or gated).
  void count_innovation(InnovationStats& stats) const {
    if (rows > 0) stats.add(nis, rows, !used && reason == RejectReason::kChi2Gate);
  }
};

// Levelling accumulator (alignment.cpp).
struct Leveller {
  double static_time_s = 0.0;  // stationary time accumulated
  Eigen::Vector3d dvel_sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d dtheta_sum = Eigen::Vector3d::Zero();
  double window_time_s = 0.0;
  Eigen::Vector3d window_dvel = Eigen::Vector3d::Zero();
  Eigen::Vector3d window_dtheta = Eigen::Vector3d::Zero();
  double window_f_sq = 0.0;
  int window_count = 0;
  double since_start_s = 0.0;
  // The previous window's mean specific force, the current run's first, and whether every window
  // of the run was quiet by the scatter or by speed evidence (true) rather than by a steady mean
  // force alone (alignment.cpp).
  bool have_previous_mean = false;
  Eigen::Vector3d previous_mean_force = Eigen::Vector3d::Zero();
  Eigen::Vector3d run_reference_force = Eigen::Vector3d::Zero();
  bool run_at_rest = true;
};

// Stationary detector (control/stationary_control.cpp).
struct StationaryState {
  double window_time_s = 0.0;
  int window_count = 0;
  Eigen::Vector3d sum_rate = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_force = Eigen::Vector3d::Zero();
  double sum_force_sq = 0.0;
  double sum_rate_sq = 0.0;  // of |rate|^2, for the scatter that vibration adds to the window mean
  bool previous_quiet = false;
  bool stationary = false;
  Eigen::Vector3d reference_force = Eigen::Vector3d::Zero();  // mean specific force when it began
};

// Dual-antenna baseline against course over ground (control/baseline_check.hpp).
struct BaselineCheckState {
  double antenna_yaw_rad = 0.0;  // vehicle yaw implied by the latest GNSS heading
  std::int64_t antenna_yaw_ns = INT64_MIN;
  int mismatches = 0;            // consecutive epochs of disagreement
  bool offset_detected = false;  // flagged: GNSS heading rejected, heading from the course
  double offset_rad = 0.0;       // antenna yaw minus course when flagged
};

// GNSS control (control/gnss_control.cpp).
struct GnssControlState {
  BaselineCheckState baseline;
  std::int64_t last_position_ns = INT64_MIN;     // last accepted (or re-anchored) position
  std::int64_t position_reject_since_ns = INT64_MIN;  // start of the current rejection run
  std::int64_t last_velocity_ns = INT64_MIN;
  std::int64_t velocity_reject_since_ns = INT64_MIN;
  std::int64_t last_heading_ns = INT64_MIN;
  GnssFixType last_fix = GnssFixType::kNone;
  // RTK fixed after a worse solution: the first fixed position used since brings the correction
  // the output blends (output_blend.hpp).
  bool blend_next_fixed = false;
  // The newest fix seen, kept to place the filter when the heading becomes known.
  bool have_fix = false;
  GnssPosition latest_fix;
  std::int64_t last_speed_ns = INT64_MIN;
  double last_speed_mps = 0.0;  // GNSS ground speed, for stationary detection
  std::int64_t last_receiver_velocity_ns = INT64_MIN;  // last GnssVelocity input of any receiver
  // The previous fix of the primary receiver and the velocity-matching force integral at it: the
  // velocity from two fixes aligns the heading when the receiver reports no velocity
  // (control/gnss_heading_alignment.hpp).
  struct PairedFix {
    GnssPosition fix;
    Eigen::Vector2d force_integral_mps = Eigen::Vector2d::Zero();
  };
  std::optional<PairedFix> previous_primary_fix;
  GnssJumpState jump;  // steps of the primary receiver's fixes (control/gnss_jump_check.hpp)
};

// The latest count of one tick stream (input stream and channel count), kept to difference the
// next one against (control/odometry_control.cpp).
struct TickReference {
  bool have = false;
  WheelTicks ticks;
};

struct OdometryState {
  std::array<TickReference, 4> tick_references{};  // a few tick streams at once (wheels + vehicle)
  std::int64_t last_nhc_ns = INT64_MIN;
  std::int64_t last_speed_ns = INT64_MIN;
  double last_speed_mps = 0.0;
};

// Magnetometer control (control/magnetometer_control.cpp): the modelled declination and where.
struct MagnetometerState {
  std::optional<double> model_declination_rad;
  double lat_rad = 0.0, lon_rad = 0.0;  // where it was computed
};

// Barometer control (control/baro_control.cpp): filter height = pressure altitude + offset.
struct BaroState {
  bool anchored = false;
  double offset_m = 0.0;
  double anchor_std_m = 0.0;  // the filter's height std when anchored
};

// Accelerometer tilt aiding (control/tilt_control.cpp): the specific force of the current window.
struct TiltState {
  double window_time_s = 0.0;
  Eigen::Vector3d sum_dvel = Eigen::Vector3d::Zero();  // raw, vehicle frame
  std::uint64_t updates = 0;
};

struct ModeState {
  NavMode mode = NavMode::kInitializing;
  std::uint32_t reached_mask = 0;  // bit per NavMode value
  bool levelled = false;
  bool heading_known = false;
  bool position_known = false;
  bool diverged = false;  // set by a divergence restart, cleared on reaching Navigation
  std::int64_t last_absolute_position_ns = INT64_MIN;
  std::int64_t last_imu_fault_ns = INT64_MIN;
  std::int64_t navigating_since_ns = INT64_MIN;  // start of the current navigating stretch
  // Event counters (kept across restarts; the Engine reports them in FilterStats).
  std::uint64_t restarts = 0;
  std::uint64_t divergences = 0;  // of restarts: those check_divergence() made
  std::uint64_t gnss_recoveries = 0;
  std::uint64_t zupts = 0;
  std::uint64_t nhc_updates = 0;
  InnovationStats nhc_innovation;  // of the constraint updates tried
};

struct FilterCore {
  NavState x;
  Ekf ekf;
  StrapdownMemory memory;
  ProcessAccumulator step;
  LocalEarth earth;
  std::int64_t earth_cell = INT64_MIN;  // covariance grid step `earth` was computed in
  // State time the covariance was last brought to (flush_covariance): a measurement stamped at or
  // after it can still be fused at the end of the pending step without re-propagation.
  std::int64_t covariance_time_ns = INT64_MIN;
  StateVector noise_density = StateVector::Zero();
  StateVector variance_floor = StateVector::Zero();
  Eigen::Vector3d rate_b_rps = Eigen::Vector3d::Zero();    // compensated, newest sample
  Eigen::Vector3d force_b_mps2 = Eigen::Vector3d::Zero();  // compensated, newest sample
  // The NED acceleration low-passed (kOffsetAccelTau_s), kept while the GNSS time offset is
  // estimated: the regressor of the offset in the GNSS velocity model (fix = v + a dt).
  Eigen::Vector3d accel_lp_ned_mps2 = Eigen::Vector3d::Zero();

  Leveller leveller;
  VelocityMatchWindow velocity_match;
  StationaryState stationary;
  GnssControlState gnss;
  OdometryState odometry;
  AdaptationState adaptation;
  MagnetometerState magnetometer;
  BaroState baro;
  TiltState tilt;
  ModeState mode;
  OutputBlend output_blend;
  RecordHook record;  // forward-pass recording for the smoother; kept across restart()

  // Back to Init with the configured priors (keeps modes reached and stats elsewhere).
  void restart(const FilterOptions& o);
  // One IMU interval (raw increments in the vehicle frame): strapdown and covariance once
  // levelled (true), the levelling accumulator before (false: nothing to constrain yet).
  bool propagate(const FilterOptions& o, const ImuIncrement& raw);
  // After each propagated interval: the stationary detector with ZUPT / ZARU, the non-holonomic
  // constraint when due, then the mode and divergence checks. Apart from propagate() so that the
  // pseudo-measurements are a step of their own, in this order, before any aiding at the sample.
  void apply_constraints(const FilterOptions& o, const ImuIncrement& raw);
  // Brings the covariance up to the state time (before any update).
  void flush_covariance(const FilterOptions& o);
  // Whether the covariance is at the state time (no IMU interval waits in `step`): an update
  // now costs no covariance step of its own.
  bool covariance_current() const { return step.dt_s <= 0.0; }
  // Gate, update, correct the nominal state. `gate` <= 0: no gate.
  FuseResult apply(const FilterOptions& o, const Observation& obs, double gate);
  StateView view(double shift_s) const {
    StateView v(x, earth, rate_b_rps, shift_s);
    v.accel_ned_mps2 = accel_lp_ned_mps2;
    return v;
  }
  // NaN, or a covariance that no longer means anything: restart and flag it.
  bool check_divergence(const FilterOptions& o);
  bool navigating() const { return mode.levelled && mode.heading_known && mode.position_known; }
};

// Fuse one aiding measurement (anything but IMU) at `shift_s` from the state time.
FuseResult fuse_measurement(FilterCore& core, const FilterOptions& o, const Measurement& m,
                            double shift_s);

}  // namespace navfuse::filter

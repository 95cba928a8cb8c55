#include "filter/filter_core.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "filter/alignment.hpp"
#include "filter/control/odometry_control.hpp"
#include "filter/control/stationary_control.hpp"
#include "filter/control/tilt_control.hpp"
#include "filter/measurement_kinds.hpp"
#include "filter/mode_machine.hpp"
#include "filter/smoother/forward_record.hpp"

namespace navfuse::filter {
namespace {

// Smallest variances kept on the diagonal: far below anything the sensors resolve, large enough
// that rounding never makes P indefinite.
StateVector variance_floor_for(const FilterOptions& o) {
  StateVector f = StateVector::Zero();
  f.segment<3>(sx::kPos).setConstant(1e-8);
  f.segment<3>(sx::kVel).setConstant(1e-10);
  f.segment<3>(sx::kAtt).setConstant(1e-14);
  f.segment<3>(sx::kGyroBias).setConstant(1e-18);
  f.segment<3>(sx::kAccelBias).setConstant(1e-14);
  f(sx::kWheelScale) = 1e-12;
  f(sx::kMountPitch) = f(sx::kMountYaw) = 1e-14;
  f.segment<3>(sx::kLeverArm).setConstant(1e-10);
  f.segment<3>(sx::kGyroScale).setConstant(1e-14);
  f.segment<3>(sx::kAccelScale).setConstant(1e-14);
  f(sx::kGnssTimeOffset) = 1e-12;  // s^2: a microsecond
  for (int i = 0; i < sx::kCount; ++i) {
    if (!o.states.is_active(i)) f(i) = 0.0;
  }
  return f;
}

}  // namespace

void FilterCore::restart(const FilterOptions& o) {
  if (record.sink != nullptr) record_restart(*this);
  const std::int64_t t = x.time_ns;
  x = NavState{};
  x.time_ns = t;
  x.gnss_lever_arm_m = o.gnss_lever_arm_m;
  ekf = Ekf{};
  ekf.n = o.states.active_dimension();
  memory = StrapdownMemory{};
  step = ProcessAccumulator{};
  covariance_time_ns = t;
  earth = LocalEarth::at(0.0, 0.0);
  noise_density = process_noise_density(o);
  variance_floor = variance_floor_for(o);
  rate_b_rps.setZero();
  force_b_mps2.setZero();
  leveller = Leveller{};
  velocity_match = VelocityMatchWindow{};
  stationary = StationaryState{};
  gnss = GnssControlState{};
  odometry = OdometryState{};
  magnetometer = MagnetometerState{};
  baro = BaroState{};
  tilt = TiltState{.window_time_s = 0.0, .sum_dvel = Eigen::Vector3d::Zero(), .updates = tilt.updates};
  const AdaptationState previous_adaptation = adaptation;
  adaptation = AdaptationState{};
  adaptation.inflations = previous_adaptation.inflations;  // counters survive restarts
  adaptation.max_process_noise_scale = previous_adaptation.max_process_noise_scale;
  output_blend.offset_ned_m.setZero();  // a restart has no position to be continuous with
  const ModeState previous = mode;
  mode = ModeState{};
  mode.reached_mask = previous.reached_mask;
  mode.diverged = previous.diverged;
  mode.restarts = previous.restarts;
  mode.divergences = previous.divergences;
  mode.gnss_recoveries = previous.gnss_recoveries;
  mode.zupts = previous.zupts;
  mode.nhc_updates = previous.nhc_updates;
  mode.nhc_innovation = previous.nhc_innovation;
  update_mode(*this, o);
}

namespace {
// The GNSS time offset is seen only in manoeuvres (on a straight, v dt is a position error), and
// the first ones come while the heading, velocity and position still carry what the alignment
// took from fixes stamped dt off. Its variance collapses there to a few milliseconds around a
// value far from the truth, and at its random walk of 1 ms / sqrt(h) (process_model.cpp) the
// state then crept towards the truth at ~0.02 ms/s: on parking_drive (IMU 125 ms late, land
// platform, data-sheet noise, offset estimated from the default prior) it ended the 9 minutes at
// 49-68 ms in three draws. For the first two minutes of navigation it walks at 3 ms / sqrt(s),
// enough for the turns of those minutes to carry it to the truth (114-124 ms; after them it is
// as precise as before: tests/filter/gnss_time_offset_scenario_test.cpp).
constexpr double kOffsetSettle_s = 120.0;
constexpr double kOffsetSettleRw_s = 3e-3;  // s / sqrt(s)
}  // namespace

bool FilterCore::propagate(const FilterOptions& o, const ImuIncrement& raw) {
  if (!mode.levelled) {
    x.time_ns = raw.time_ns;
    feed_leveller(*this, o, raw);
    update_mode(*this, o);
    return false;
  }
  const ImuIncrement comp = compensate(raw, x);
  rate_b_rps = comp.dtheta_rad / comp.dt_s;
  force_b_mps2 = comp.dvel_mps / comp.dt_s;
  // Covariance steps end on a fixed time grid, so measurements stamped on the same grid (GNSS,
  // odometry and the constraints at 5-20 Hz) find the covariance already current and the update
  // costs no extra propagation.
  const std::int64_t grid_ns = std::max<std::int64_t>(1, std::llround(o.covariance_interval_s * 1e9));
  // Gravity, earth rate and radii are refreshed once per grid step (<= 50 ms: at most a few
  // metres of travel, a change of ~1e-5 m/s^2 in gravity), not at every measurement update.
  if (step.dt_s == 0.0 && x.time_ns / grid_ns != earth_cell) {
    earth = LocalEarth::at(x.lat_rad, x.height_m);
    earth_cell = x.time_ns / grid_ns;
  }
  const std::int64_t previous_ns = x.time_ns;
  if (record.sink != nullptr) record_step_start(*this);
  strapdown_step(x, memory, comp, earth);
  decay_output_blend(*this, o, comp.dt_s);
  if (o.states.gnss_time_offset) {
    // One sample's acceleration carries the whole vibration (on parking_drive the engine's tone
    // alone is 0.5 m/s^2 against manoeuvres of 1-3 m/s^2): as the regressor of the offset in the
    // GNSS models it is an error in the variables, which pulls the estimate towards zero. 50 ms
    // averages the vibration out and lags a 3 s car-park turn by little (a walker's 2 Hz steps by
    // a third of their swing: the walk's estimate stays within 7 ms of zero, README).
    constexpr double kOffsetAccelTau_s = 0.05;
    const Eigen::Vector3d a = x.q_nb * force_b_mps2 + earth.gravity_ned_mps2;
    accel_lp_ned_mps2 += (1.0 - std::exp(-comp.dt_s / kOffsetAccelTau_s)) * (a - accel_lp_ned_mps2);
  }
  if (!mode.heading_known) accumulate_velocity_match(velocity_match, x.q_nb.toRotationMatrix(), comp.dvel_mps);
  step.add(comp);
  if (record.sink != nullptr) record_imu(*this, o);
  if (x.time_ns / grid_ns != previous_ns / grid_ns || step.dt_s >= o.covariance_interval_s - 1e-9) {
    flush_covariance(o);
  }
  return true;
}

void FilterCore::apply_constraints(const FilterOptions& o, const ImuIncrement& raw) {
  update_stationary(*this, o, raw);
  update_accel_tilt(*this, o, raw);
  apply_nonholonomic(*this, o);
  update_mode(*this, o);
  check_divergence(o);
}

void FilterCore::flush_covariance(const FilterOptions& o) {
  if (step.dt_s <= 0.0) return;
  covariance_time_ns = x.time_ns;
  const bool offset_settling = o.states.gnss_time_offset && mode.navigating_since_ns != INT64_MIN &&
                               seconds_since(x.time_ns, mode.navigating_since_ns) < kOffsetSettle_s;
  if (adaptation.process_noise_scale == 1.0 && !offset_settling) {
    propagate_covariance(ekf.p, ekf.n, x, earth, step, noise_density);
  } else {
    // Vibration and unmodelled errors show up as extra velocity and attitude random walk.
    StateVector q = noise_density;
    q.segment<3>(sx::kVel) *= adaptation.process_noise_scale;
    q.segment<3>(sx::kAtt) *= adaptation.process_noise_scale;
    if (offset_settling) q(sx::kGnssTimeOffset) = kOffsetSettleRw_s * kOffsetSettleRw_s;
    propagate_covariance(ekf.p, ekf.n, x, earth, step, q);
  }
  // Vertical-gyro mode (MIP §6.2): the heading is relative, not estimated. Estimating it through
  // the earth-rate coupling from a heading error of tens of degrees would be far outside the
  // linearisation and drags roll and pitch with it.
  if (mode.levelled && !mode.heading_known) ekf.reset_states(sx::kAttDown, 1, 0.0);
  ekf.guard(variance_floor);
  if (record.sink != nullptr) record_propagation(*this);  // reads `step`: before it is cleared
  step = ProcessAccumulator{};
}

FuseResult FilterCore::apply(const FilterOptions& o, const Observation& obs, double gate) {
  if (obs.rows() == 0) return FuseResult::reject(RejectReason::kInvalid);
  flush_covariance(o);
  const UpdateResult r = ekf.update(obs, gate);
  if (r.singular) return FuseResult::reject(RejectReason::kNumerical);
  FuseResult out = r.accepted ? FuseResult::ok() : FuseResult::reject(RejectReason::kChi2Gate);
  out.rows = obs.rows();
  out.nis = r.nis;
  for (int i = 0; i < out.rows; ++i) {
    out.residual[static_cast<std::size_t>(i)] = obs.residual(i);
    out.innovation_std[static_cast<std::size_t>(i)] = std::sqrt(r.s_diag(i));
  }
  if (!r.accepted) return out;
  std::optional<NavState> before;
  if (record.sink != nullptr) before = x;
  inject_error(x, r.dx);
  gnss.jump.corrections_ned_m -= r.dx.segment<3>(sx::kPos);  // dx is estimate minus truth
  ekf.guard(variance_floor);
  if (before) record_update(*this, *before, obs, r);
  return out;
}

bool FilterCore::check_divergence(const FilterOptions& o) {
  const bool state_finite = std::isfinite(x.lat_rad) && std::isfinite(x.lon_rad) &&
                            std::isfinite(x.height_m) && x.vel_ned_mps.allFinite() &&
                            x.q_nb.coeffs().allFinite() && x.gyro_bias_rps.allFinite() &&
                            x.accel_bias_mps2.allFinite();
  const double horizontal_var = ekf.p(sx::kPos, sx::kPos) + ekf.p(sx::kPos + 1, sx::kPos + 1);
  const bool lost = navigating() && horizontal_var > o.divergence_position_std_m * o.divergence_position_std_m;
  if (state_finite && ekf.finite() && !lost) return false;
  mode.diverged = true;
  ++mode.restarts;
  ++mode.divergences;
  restart(o);
  return true;
}

FuseResult fuse_measurement(FilterCore& core, const FilterOptions& o, const Measurement& m,
                            double shift_s) {
  const FuseFunction fuse = kind_row(kind_of(m)).fuse;
  const FuseResult r = fuse != nullptr ? fuse(core, o, m, shift_s) : FuseResult::reject(RejectReason::kInvalid);
  update_mode(core, o);
  return r;
}

}  // namespace navfuse::filter

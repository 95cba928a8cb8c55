#include "filter/engine.hpp"

#include <algorithm>
#include <cmath>

#include "core/rotation/rotation.hpp"
#include "filter/alignment.hpp"
#include "filter/measurement_kinds.hpp"
#include "filter/solution.hpp"

namespace navfuse::filter {
namespace {

// IMU history capacity: the latency window at up to 1 kHz, plus a checkpoint interval.
constexpr double kMaxImuRate_hz = 1000.0;
// Aiding measurements held for re-propagation (a 1 s window of ~10 streams at up to 20 Hz).
constexpr std::size_t kMaxEntries = 512;

std::int64_t to_ns(double s) { return static_cast<std::int64_t>(std::llround(s * 1e9)); }

}  // namespace

Engine::Engine(const FilterOptions& options)
    : options_(options),
      imu_history_(static_cast<std::size_t>(
          (std::max(options.max_latency_s, 0.0) + 2.0 * options.checkpoint_interval_s) * kMaxImuRate_hz) + 16),
      checkpoints_(static_cast<std::size_t>(
          std::ceil(std::max(options.max_latency_s, 0.0) / std::max(options.checkpoint_interval_s, 1e-3))) + 2) {
  entries_.reserve(kMaxEntries);
  imu_input_.set_mounting(rot::dcm_from_rpy(options_.mounting_rpy_rad));
  core_.restart(options_);
}

void Engine::process(const Measurement& m) {
  const MeasurementKind kind = kind_of(m);
  const MeasurementKindRow& row = kind_row(kind);
  if (!fuses(kind)) {
    ++stats_.of(kind).ignored;
    return;
  }
  if (auto reason = row.check(m)) {
    ++stats_.of(kind).rejected[static_cast<std::size_t>(*reason)];
    return;
  }
  if (const double offset_s = options_.time_offset_s(kind); offset_s != 0.0) {
    // Onto the common time base before anything (ordering, latency, interpolation) uses it.
    Measurement shifted = m;
    header_of(shifted).time_ns += to_ns(offset_s);
    dispatch(kind, shifted);
    return;
  }
  dispatch(kind, m);
}

void Engine::dispatch(MeasurementKind kind, const Measurement& m) {
  if (kind == MeasurementKind::kImu) {
    process_imu(std::get<ImuSample>(m));
  } else {
    process_aiding(m);
  }
}

void Engine::process_imu(const ImuSample& s) {
  KindStats& st = stats_.of(MeasurementKind::kImu);
  const std::int64_t t = s.header.time_ns;
  bool restarted = false;
  if (imu_input_.has_previous()) {
    if (t <= imu_input_.previous_time_ns()) {
      ++st.rejected[static_cast<std::size_t>(RejectReason::kTimeBackwards)];
      return;
    }
    if (static_cast<double>(t - imu_input_.previous_time_ns()) * 1e-9 > options_.max_imu_gap_s) {
      // The state cannot be carried across the gap: start again from this sample. The sample is
      // counted once, as time_gap (not also as used below), so that decoded = used + rejected.
      ++st.rejected[static_cast<std::size_t>(RejectReason::kTimeGap)];
      restarted = true;
      ++core_.mode.restarts;
      core_.restart(options_);
      forget_history();
      imu_input_.reset();
    }
  }
  imu_time_source_ = s.header.time_source;
  if (s.saturation != 0) core_.mode.last_imu_fault_ns = t;
  const std::optional<ImuIncrement> inc = imu_input_.convert(s);
  if (!restarted) ++st.used;
  if (!inc) return;
  const ImuRecord record{*inc, t + to_ns(0.5 * inc->dt_s), ++imu_seq_};
  imu_history_.push_back(record);
  run_increment(record);
  if (initial_heading_rad_ && core_.mode.levelled) take_initial_heading();
  ++imu_epoch_;
  solution_dirty_ = true;
}

void Engine::run_increment(const ImuRecord& record) {
  if (core_.propagate(options_, record.increment)) core_.apply_constraints(options_, record.increment);
  previous_horizon_ns_ = latest_horizon_ns_;
  latest_horizon_ns_ = record.horizon_ns;
  fuse_due(record.horizon_ns);
  maybe_checkpoint(record);
}

void Engine::fuse_due(std::int64_t horizon_ns) {
  // Entries stamped before the previous horizon are fused already (by the fuse_due() that reached
  // that horizon, on arrival in process_aiding, or dropped), but for those from unfused_from_ns_
  // on: waiting for the covariance grid, or un-fused by replay_from(). So the scan starts at the
  // earlier of the two instead of at the ~1 s of fused entries kept for re-propagation (a walk
  // over ~60 entries per IMU sample).
  const std::int64_t from_ns = std::min(previous_horizon_ns_, unfused_from_ns_);
  unfused_from_ns_ = INT64_MAX;
  auto e = std::lower_bound(entries_.begin(), entries_.end(), from_ns,
                            [](const Entry& entry, std::int64_t t) { return entry.time_ns < t; });
  for (; e != entries_.end() && e->time_ns < horizon_ns; ++e) {
    if (e->applied()) continue;
    if (waits_for_grid(*e)) {
      unfused_from_ns_ = std::min(unfused_from_ns_, e->time_ns);
      continue;
    }
    fuse_entry(*e);
  }
}

bool Engine::waits_for_grid(const Entry& e) const {
  return waits_for_covariance_grid(kind_of(e.m)) && !core_.covariance_current();
}

void Engine::fuse_entry(Entry& e) {
  const double shift_s = static_cast<double>(e.time_ns - core_.x.time_ns) * 1e-9;
  const FuseResult r = fuse_measurement(core_, options_, e.m, shift_s);
  e.fused_order = ++fused_order_;
  if (!e.counted) {
    count(kind_of(e.m), r);
    if (innovation_sink_ != nullptr) innovation_sink_(innovation_context_, e.m, r);
    e.counted = true;
  }
}

void Engine::count(MeasurementKind kind, const FuseResult& r) {
  KindStats& st = stats_.of(kind);
  r.count_innovation(st.innovation);
  if (r.used) {
    ++st.used;
  } else {
    ++st.rejected[static_cast<std::size_t>(r.reason)];
  }
}

void Engine::maybe_checkpoint(const ImuRecord& record) {
  if (options_.max_latency_s <= 0.0) {
    // No re-propagation: fused measurements are never needed again.
    while (!entries_.empty() && entries_.front().applied()) entries_.erase(entries_.begin());
    return;
  }
  if (last_checkpoint_ns_ != INT64_MIN &&
      static_cast<double>(core_.x.time_ns - last_checkpoint_ns_) * 1e-9 <
          options_.checkpoint_interval_s - 1e-9) {
    return;
  }
  checkpoints_.push_back(Checkpoint{core_, record.horizon_ns, record.seq, fused_order_});
  last_checkpoint_ns_ = core_.x.time_ns;
  // Measurements already inside the oldest snapshot (fused before it was taken) can never be
  // re-fused.
  const std::uint64_t oldest = checkpoints_.front().fused_order;
  auto keep = std::find_if(entries_.begin(), entries_.end(),
                           [&](const Entry& e) { return !(e.applied() && e.fused_order <= oldest); });
  entries_.erase(entries_.begin(), keep);
}

std::uint64_t Engine::pending(MeasurementKind kind) const {
  return static_cast<std::uint64_t>(
      std::count_if(entries_.begin(), entries_.end(), [kind](const Entry& e) { return !e.counted && kind_of(e.m) == kind; }));
}

void Engine::process_aiding(const Measurement& m) {
  const std::int64_t t = header_of(m).time_ns;
  const MeasurementKind kind = kind_of(m);
  // The difference in double: a checksum-valid time centuries off must not overflow int64 (UB).
  if (imu_seq_ > 0 && (static_cast<double>(core_.x.time_ns) - static_cast<double>(t)) * 1e-9 > options_.max_latency_s) {
    count(kind, FuseResult::reject(RejectReason::kTooLate));
    return;
  }
  if (entries_.size() >= kMaxEntries) {
    Entry& oldest = entries_.front();
    if (!oldest.counted) count(kind_of(oldest.m), FuseResult::reject(RejectReason::kOverflow));
    entries_.erase(entries_.begin());
  }
  auto pos = std::upper_bound(entries_.begin(), entries_.end(), t,
                              [](std::int64_t time, const Entry& e) { return time < e.time_ns; });
  pos = entries_.insert(pos, Entry{m, t, 0, false});
  if (imu_seq_ == 0 || t >= latest_horizon_ns_) return;  // waits for the IMU to reach it
  if (waits_for_grid(*pos) && t >= core_.covariance_time_ns) {
    // Late, but inside the covariance step still open: fused at its end, as if it had come in
    // time (no re-propagation).
    unfused_from_ns_ = std::min(unfused_from_ns_, t);
    return;
  }
  if (t >= previous_horizon_ns_) {
    fuse_entry(*pos);
    // A snapshot taken at this sample (maybe_checkpoint) is from before the entry, though the
    // entry is stamped before its horizon: brought up to date, a re-propagation from it holds the
    // entry fused where it was, as one that had come in time.
    if (!checkpoints_.empty() && checkpoints_.back().seq == imu_seq_) {
      checkpoints_.back().core = core_;
      checkpoints_.back().fused_order = fused_order_;
    }
    solution_dirty_ = true;
    return;
  }
  replay_from(t);
  solution_dirty_ = true;
}

void Engine::replay_from(std::int64_t t) {
  // Newest snapshot that does not yet contain the measurement, with its IMU samples still held.
  std::size_t c = checkpoints_.size();
  while (c > 0 && checkpoints_[c - 1].horizon_ns > t) --c;
  const bool found = c > 0 && !imu_history_.empty() &&
                     imu_history_.front().seq <= checkpoints_[c - 1].seq + 1;
  if (!found) {
    auto it = std::find_if(entries_.begin(), entries_.end(),
                           [&](const Entry& e) { return e.time_ns == t && !e.applied(); });
    if (it != entries_.end()) {
      count(kind_of(it->m), FuseResult::reject(RejectReason::kTooLate));
      entries_.erase(it);
    }
    return;
  }
  const Checkpoint& cp = checkpoints_[c - 1];
  const std::uint64_t from_seq = cp.seq;
  const std::int64_t from_horizon = cp.horizon_ns;
  const std::uint64_t from_order = cp.fused_order;
  core_ = cp.core;
  last_checkpoint_ns_ = core_.x.time_ns;
  while (checkpoints_.size() > c) checkpoints_.pop_back();
  // Everything fused after the snapshot is fused again: by time that is every entry from its
  // horizon on, and also an older one fused later (it arrived late within an IMU interval, or
  // waited for the covariance grid), which the snapshot does not hold either.
  unfused_from_ns_ = INT64_MAX;
  for (Entry& e : entries_) {
    if (e.fused_order > from_order) e.fused_order = 0;
    if (!e.applied()) unfused_from_ns_ = std::min(unfused_from_ns_, e.time_ns);
  }
  latest_horizon_ns_ = from_horizon;
  const std::size_t first = static_cast<std::size_t>(from_seq + 1 - imu_history_.front().seq);
  for (std::size_t i = first; i < imu_history_.size(); ++i) run_increment(imu_history_[i]);
  ++stats_.replays;
}

void Engine::forget_history() {
  // Aiding still waiting for the IMU belongs to the stretch that was lost: counted as time_gap,
  // not dropped from the counts (decoded = used + rejected + pending).
  for (const Entry& e : entries_) {
    if (!e.counted) count(kind_of(e.m), FuseResult::reject(RejectReason::kTimeGap));
  }
  drop_snapshots_and_entries();
  imu_history_.clear();
  latest_horizon_ns_ = previous_horizon_ns_ = INT64_MIN;
}

const NavSolution& Engine::solution() const {
  if (solution_dirty_) fill_solution();
  return solution_;
}

void Engine::fill_solution() const {
  capture_solution(solution_inputs_);
  fill_nav_solution(solution_inputs_, solution_);
  solution_dirty_ = false;
}

void Engine::capture_solution(SolutionInputs& in) const {
  filter::capture_solution(core_, options_, imu_input_.mounting(), imu_time_source_, in);
}

bool Engine::solution_valid() const {
  return core_.mode.mode == NavMode::kNavigation || core_.mode.mode == NavMode::kDeadReckoning;
}

const FilterStats& Engine::stats() const {
  stats_view_ = stats_;
  stats_view_.resets = core_.mode.restarts;
  stats_view_.gnss_recoveries = core_.mode.gnss_recoveries;
  stats_view_.zupts = core_.mode.zupts;
  stats_view_.accel_tilt_updates = core_.tilt.updates;
  stats_view_.nhc_updates = core_.mode.nhc_updates;
  stats_view_.nhc_innovation = core_.mode.nhc_innovation;
  stats_view_.covariance_inflations = core_.adaptation.inflations;
  stats_view_.output_jumps_blended = core_.output_blend.jumps_blended;
  stats_view_.process_noise_scale = core_.adaptation.process_noise_scale;
  stats_view_.max_process_noise_scale = core_.adaptation.max_process_noise_scale;
  stats_view_.max_gnss_position_noise_scale = core_.adaptation.position_noise.max_scale;
  stats_view_.max_gnss_velocity_noise_scale = core_.adaptation.velocity_noise.max_scale;
  return stats_view_;
}

void Engine::reset(std::uint32_t mask) {
  if ((mask & kResetFilter) != 0) {
    initial_heading_rad_.reset();
    ++core_.mode.restarts;
    core_.restart(options_);
  } else {
    core_.flush_covariance(options_);
    if ((mask & kResetHeading) != 0 && core_.mode.levelled) {
      core_.mode.heading_known = false;
      core_.ekf.reset_states(sx::kAttDown, 1, 0.0);  // relative heading, not estimated
    }
    if ((mask & kResetBiases) != 0) {
      const auto& n = options_.imu;
      core_.x.gyro_bias_rps.setZero();
      core_.x.accel_bias_mps2.setZero();
      core_.ekf.reset_states(sx::kGyroBias, 3, n.initial_gyro_bias_std_rps * n.initial_gyro_bias_std_rps);
      core_.ekf.reset_states(sx::kAccelBias, 3, n.initial_accel_bias_std_mps2 * n.initial_accel_bias_std_mps2);
    }
    if ((mask & kResetPosition) != 0) {
      core_.mode.position_known = false;
      core_.ekf.reset_states(sx::kPos, 3, 1e6);
    }
  }
  // Snapshots from before the reset must not be replayed into it.
  drop_snapshots_and_entries();
  solution_dirty_ = true;
}

void Engine::set_gnss_lever_arm(const Eigen::Vector3d& lever_arm_m, int antenna) {
  if (antenna == 1) {
    options_.gnss_secondary_lever_arm_m = lever_arm_m;
    return;
  }
  options_.gnss_lever_arm_m = lever_arm_m;
  core_.x.gnss_lever_arm_m = lever_arm_m;
  drop_snapshots_and_entries();
}

void Engine::drop_snapshots_and_entries() {
  entries_.clear();
  unfused_from_ns_ = INT64_MAX;
  checkpoints_.clear();
  last_checkpoint_ns_ = INT64_MIN;
}

void Engine::set_mounting(const Eigen::Vector3d& rpy_rad) {
  options_.mounting_rpy_rad = rpy_rad;
  imu_input_.set_mounting(rot::dcm_from_rpy(rpy_rad));
  reset(kResetFilter);
}

void Engine::set_wheel_lever_arm(const Eigen::Vector3d& lever_arm_m) {
  options_.wheel_lever_arm_m = lever_arm_m;
}

bool Engine::set_initial_heading(double heading_rad) {
  if (core_.mode.heading_known || options_.fuses(MeasurementKind::kMagnetometer)) return false;
  initial_heading_rad_ = heading_rad;
  if (core_.mode.levelled) take_initial_heading();
  return true;
}

void Engine::take_initial_heading() {
  if (!core_.mode.heading_known) {
    set_heading(core_, *initial_heading_rad_, options_.initial_heading_std_rad);
    // Checkpoints before the new heading would restore the old one on a re-propagation.
    checkpoints_.clear();
    last_checkpoint_ns_ = INT64_MIN;
    solution_dirty_ = true;
  }
  initial_heading_rad_.reset();
}

void Engine::set_aiding(MeasurementKind kind, bool on) {
  if (kind == MeasurementKind::kImu) return;
  const std::uint32_t bit = 1u << static_cast<unsigned>(kind);
  options_.aiding_off_mask = on ? options_.aiding_off_mask & ~bit : options_.aiding_off_mask | bit;
}

std::vector<NavMode> Engine::modes_reached() const {
  std::vector<NavMode> modes;
  for (unsigned i = 0; i <= static_cast<unsigned>(NavMode::kDeadReckoning); ++i) {
    if ((core_.mode.reached_mask & (1u << i)) != 0) modes.push_back(static_cast<NavMode>(i));
  }
  return modes;
}

}  // namespace navfuse::filter

#include "apps/fusion/fusion_runner.hpp"

#include <algorithm>
#include <cmath>

namespace navfuse::apps {
namespace {
bool is_gnss(MeasurementKind k) {
  return k == MeasurementKind::kGnssPosition || k == MeasurementKind::kGnssVelocity ||
         k == MeasurementKind::kGnssHeading;
}
}  // namespace

FusionRunner::FusionRunner(const filter::FilterOptions& filter_options, const Options& options,
                           FusionObserver& observer)
    : engine_(filter_options),
      observer_(observer),
      solutions_(options.solutions),
      outages_(options.gnss_outages),
      imu_guard_(std::llround(engine_.options().max_imu_gap_s * 1e9)),
      rate_(options.output_rate_hz),
      last_engine_epoch_(engine_.imu_epoch()) {}

void FusionRunner::offer(const Measurement& m, std::int64_t arrival_ns) {
  const MeasurementKind kind = kind_of(m);
  ++counts_.decoded[static_cast<std::size_t>(kind)];
  observer_.on_offered(m);
  if (const auto reason = gate_.check(m, engine_.fuses(kind))) {
    counts_.count_gated(kind, *reason);
    ++gated_total_;
    return;
  }
  if (kind == MeasurementKind::kImu) {
    offer_imu(m, arrival_ns);
    return;
  }
  if (outages_ && first_imu_ && is_gnss(kind) && outages_->in_outage(header_of(m).time_ns, first_imu_->time_ns)) {
    counts_.count_gated(kind, "outage");
    ++gated_total_;
    return;
  }
  if (kind == MeasurementKind::kGnssPosition) num_sats_ = std::get<GnssPosition>(m).num_sats;
  observer_.on_fused(m);
  engine_.process(m);
}

void FusionRunner::offer_imu(const Measurement& m, std::int64_t arrival_ns) {
  const ImuTimeGuard::Verdict v = imu_guard_.check(header_of(m).time_ns);
  if (v.reject_held) reject_held_imu();
  if (v.release_held) fuse_imu(held_imu_, held_arrival_ns_);
  if (v.hold) {
    held_imu_ = m;
    held_arrival_ns_ = arrival_ns;
    return;
  }
  fuse_imu(m, arrival_ns);
}

void FusionRunner::fuse_imu(const Measurement& m, std::int64_t arrival_ns) {
  observer_.on_fused(m);
  engine_.process(m);
  after_imu(std::get<ImuSample>(m), arrival_ns);
}

void FusionRunner::reject_held_imu() {
  counts_.count_gated(MeasurementKind::kImu, "time_jump");
  ++gated_total_;
}

void FusionRunner::finish() {
  if (!imu_guard_.holding()) return;
  imu_guard_.drop_held();
  reject_held_imu();
}

void FusionRunner::after_imu(const ImuSample& s, std::int64_t arrival_ns) {
  if (!first_imu_) first_imu_ = s.header;
  last_imu_ns_ = std::max(last_imu_ns_, s.header.time_ns);
  ++imu_samples_;
  if (engine_.imu_epoch() == last_engine_epoch_) return;  // the filter did not advance (rejected)
  last_engine_epoch_ = engine_.imu_epoch();

  OutputEpoch* slot = solutions_ == Solutions::kDeferred ? observer_.epoch_slot() : nullptr;
  OutputEpoch& epoch = slot != nullptr ? *slot : epoch_;
  // The state time is the solution's time (filter/solution.cpp), known without filling it.
  epoch.pose_due = rate_.due(engine_.core().x.time_ns);
  epoch.gnss_fused_total = engine_.used(MeasurementKind::kGnssPosition);
  epoch.gnss_updated = false;
  if (epoch.pose_due) {
    ++poses_;
    // GNSSInfo-style outputs go out at the first pose after a fix was fused.
    epoch.gnss_updated = epoch.gnss_fused_total != gnss_at_last_pose_;
    gnss_at_last_pose_ = epoch.gnss_fused_total;
  }
  epoch.num_sats = num_sats_;
  epoch.arrival_ns = arrival_ns;
  epoch.time_gap_restarts = engine_.time_gap_restarts();
  epoch.divergence_restarts = engine_.divergence_restarts();
  epoch.solution_deferred = solutions_ == Solutions::kDeferred;
  if (epoch.solution_deferred) {
    engine_.capture_solution(epoch.solution_inputs);
  } else if (solutions_ == Solutions::kEvery || (solutions_ == Solutions::kPoses && epoch.pose_due)) {
    epoch.solution = engine_.solution();
  }
  observer_.on_epoch(epoch, engine_);
}

void FusionRunner::fill_summary(Summary& summary, double wall_s) const {
  fill_measurement_counts(engine_, counts_, summary);
  RunStats run;
  run.wall_s = wall_s;
  run.imu_samples_per_s = wall_s > 0.0 ? static_cast<double>(imu_samples_) / wall_s : 0.0;
  for (NavMode mode : engine_.modes_reached()) run.modes_reached.emplace_back(to_string(mode));
  summary.run = run;
  summary.calibration.clear();
  for (const CalibrationGroup& g : calibration_groups(engine_.solution())) {
    if (g.estimated) summary.calibration.push_back(g);
  }
}

}  // namespace navfuse::apps

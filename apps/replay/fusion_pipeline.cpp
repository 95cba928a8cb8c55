#include "apps/replay/fusion_pipeline.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <string>

#include "apps/replay/progress_bar.hpp"
#include "core/geodesy/geoid.hpp"
#include "apps/replay/time_base_gate.hpp"

namespace navfuse::apps {
namespace {

using GatedCounts = std::array<std::map<std::string, std::uint64_t>, static_cast<std::size_t>(MeasurementKind::kCount)>;

// Used / rejected-by-reason of the filter, plus the app's own time-base rejections.
void fill_measurement_counts(const filter::FilterStats& stats, const MeasurementMerger& merger,
                             const GatedCounts& gated, Summary& summary) {
  for (std::size_t k = 0; k < summary.kinds.size(); ++k) {
    KindSummary& ks = summary.kinds[k];
    const filter::KindStats& fs = stats.kinds[k];
    ks.decoded = merger.decoded()[k];
    ks.used = fs.used;
    for (std::size_t r = 0; r < fs.rejected.size(); ++r) {
      if (fs.rejected[r] > 0) ks.rejected[std::string(filter::to_string(static_cast<filter::RejectReason>(r)))] += fs.rejected[r];
    }
    // A kind the filter does not fuse (device solutions, magnetometer...): "ignored".
    if (fs.ignored > 0) ks.rejected["ignored"] += fs.ignored;
    for (const auto& [reason, n] : gated[k]) ks.rejected[reason] += n;
  }
}

}  // namespace

PipelineResult run_fusion_pipeline(MeasurementMerger& merger, filter::Engine& engine,
                                   const PipelineOptions& options, PipelineObserver& observer) {
  TimeBaseGate gate;
  ProgressBar bar(merger.total_bytes(), options.progress_bar);
  ProgressLines lines(merger.total_bytes(), options.progress_lines_label);
  GatedCounts gated;

  // One-time set-up outside the timed loop: the solution's geoid undulation reads a 4 MB grid
  // on first use, which would otherwise count as processing time in a short replay.
  geo::GeoidGrid::egm96();

  PipelineResult result;
  std::uint64_t epoch = engine.imu_epoch();
  std::uint64_t processed = 0;
  Measurement m;
  const auto start = std::chrono::steady_clock::now();
  while (merger.next(m)) {
    observer.on_merged(m);
    const MeasurementKind kind = kind_of(m);
    if (const auto reason = gate.check(m)) {
      ++gated[static_cast<std::size_t>(kind)][std::string(*reason)];
      continue;
    }
    observer.on_fused(m);
    engine.process(m);
    if (kind == MeasurementKind::kImu) {
      const MeasurementHeader& h = header_of(m);
      if (!result.first_imu) result.first_imu = h;
      result.last_imu_ns = std::max(result.last_imu_ns, h.time_ns);
      ++result.imu_samples;
      if (engine.imu_epoch() != epoch) {
        epoch = engine.imu_epoch();
        observer.on_imu_epoch(engine);
      }
    }
    if ((++processed & 0x3FFF) == 0) {
      bar.update(merger.bytes_read());
      lines.update(merger.bytes_read());
    }
  }
  observer.on_finished();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bar.clear();

  Summary& summary = result.summary;
  summary.inputs = merger.input_summaries();
  fill_measurement_counts(engine.stats(), merger, gated, summary);
  RunStats run;
  run.wall_s = wall_s;
  run.imu_samples_per_s = wall_s > 0.0 ? static_cast<double>(result.imu_samples) / wall_s : 0.0;
  for (NavMode mode : engine.modes_reached()) run.modes_reached.emplace_back(to_string(mode));
  summary.run = run;
  return result;
}

}  // namespace navfuse::apps

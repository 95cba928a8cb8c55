#include "apps/replay/fusion_pipeline.hpp"

#include <algorithm>
#include <chrono>

#include "apps/common/measurement_counts.hpp"
#include "apps/replay/progress_bar.hpp"
#include "core/geodesy/geoid.hpp"
#include "apps/replay/time_base_gate.hpp"

namespace navfuse::apps {
PipelineResult run_fusion_pipeline(MeasurementMerger& merger, filter::Engine& engine,
                                   const PipelineOptions& options, PipelineObserver& observer) {
  TimeBaseGate gate;
  ProgressBar bar(merger.total_bytes(), options.progress_bar);
  ProgressLines lines(merger.total_bytes(), options.progress_lines_label);
  MeasurementCounts counts;

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
      counts.count_gated(kind, *reason);
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
  counts.decoded = merger.decoded();
  fill_measurement_counts(engine.stats(), counts, summary);
  RunStats run;
  run.wall_s = wall_s;
  run.imu_samples_per_s = wall_s > 0.0 ? static_cast<double>(result.imu_samples) / wall_s : 0.0;
  for (NavMode mode : engine.modes_reached()) run.modes_reached.emplace_back(to_string(mode));
  summary.run = run;
  return result;
}

}  // namespace navfuse::apps

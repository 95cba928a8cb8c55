// The loop `navfuse replay` and `navfuse bench` share: merged inputs -> time-base gate -> filter,
// with the run summary (inputs, decoded / used / rejected-by-reason per kind, run statistics)
// built the same way for both. Each command adds what it does with the stream through a
// PipelineObserver (replay: pose outputs and truth; bench: the device's solution and navfuse's
// track), so both see exactly the same fused measurements and poses.
#pragma once

#include <cstdint>
#include <optional>

#include "apps/common/summary.hpp"
#include "apps/replay/measurement_merger.hpp"
#include "core/measurements/measurements.hpp"
#include "filter/engine.hpp"

namespace navfuse::apps {

class PipelineObserver {
 public:
  virtual ~PipelineObserver() = default;
  // Every merged measurement, before the time-base gate (bench keeps device solutions whatever
  // their clock, to report a mismatch rather than silently drop them).
  virtual void on_merged(const Measurement&) {}
  // A measurement that passed the gate, just before the filter takes it.
  virtual void on_fused(const Measurement&) {}
  // The filter advanced by one IMU sample: engine.solution() is the new pose.
  virtual void on_imu_epoch(const filter::Engine&) {}
  // Every input is used up; still inside the timed part of the run (work the observer has
  // handed to another thread finishes here).
  virtual void on_finished() {}
};

struct PipelineOptions {
  bool progress_bar = false;                // redrawn bar on a terminal, for long inputs
  const char* progress_lines_label = nullptr;  // also a line every 10 % when stderr is not a terminal
};

struct PipelineResult {
  Summary summary;  // inputs, measurement counts and run statistics
  std::uint64_t imu_samples = 0;                 // IMU samples given to the filter
  std::optional<MeasurementHeader> first_imu;    // header of the first fused IMU sample
  std::int64_t last_imu_ns = 0;
};

PipelineResult run_fusion_pipeline(MeasurementMerger& merger, filter::Engine& engine,
                                   const PipelineOptions& options, PipelineObserver& observer);

}  // namespace navfuse::apps

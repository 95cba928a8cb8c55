// `navfuse smooth`'s second pass: the forward record of the replay's fusion run is smoothed
// (filter/smoother/rts_smoother.hpp) and every smoothed IMU epoch goes through the replay's own
// outputs (FusionEngine, MIP, CSV, LCM) at output.rate_hz, and to the truth comparison at the
// pose epochs, exactly as the forward solution does in `replay`: mode "smoothed".
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "apps/output/pose_outputs.hpp"
#include "apps/replay/truth_accuracy.hpp"
#include "core/measurements/measurements.hpp"
#include "filter/engine.hpp"
#include "filter/filter_options.hpp"
#include "filter/smoother/forward_record.hpp"
#include "filter/smoother/rts_smoother.hpp"

namespace navfuse::apps {

struct SmoothedPassResult {
  filter::SmootherStats stats;
  std::uint64_t poses = 0;
  std::uint64_t navigating_poses = 0;  // of those, with a smoothed (or navigating) solution
  double wall_s = 0.0;
};

// Starts recording `engine`'s forward pass for the smoother (replay --smooth, bench --reference
// smoothed); the recorder must outlive the run. Throws CommandError when its temporary file
// cannot be made.
std::unique_ptr<filter::ForwardRecorder> record_forward_pass(filter::Engine& engine);

// Throws CommandError when the record cannot be read back or an output fails. `also` (optional)
// sees every smoothed IMU sample (the calibration's starting trajectory).
SmoothedPassResult write_smoothed(filter::ForwardRecorder& record, const filter::FilterOptions& options,
                                  TimeSource time_source, double rate_hz, PoseOutputs& outputs,
                                  TruthAccuracy* accuracy,
                                  const std::function<void(const filter::SmoothedSample&)>& also = {});

}  // namespace navfuse::apps

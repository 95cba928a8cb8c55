// `replay` and `bench`: a recorded log, merged by measurement time, through the fusion runner as
// fast as the machine allows. (`run` drives the same runner from its live queue.)
#pragma once

#include <atomic>

#include "apps/common/summary.hpp"
#include "apps/fusion/fusion_runner.hpp"
#include "apps/fusion/measurement_merger.hpp"

namespace navfuse::apps {

struct LogFusionOptions {
  bool progress_bar = false;                   // redrawn bar on a terminal, for long inputs
  const char* progress_lines_label = nullptr;  // also a line every 10 % when stderr is not a terminal
  // Polled in the loop: non-zero (a signal number) stops reading; what was read is finished.
  const std::atomic<int>* interrupt = nullptr;
};

// Offers every merged measurement to `runner`, then calls the observer's on_finished(). Returns
// the summary: inputs (from the merger), measurement counts and run statistics, the rate timed
// over the loop alone (set-up before it, committing outputs after it are not included). When
// options.interrupt stops it early, summary.interrupted_by holds the signal.
Summary fuse_log(MeasurementMerger& merger, FusionRunner& runner, FusionObserver& observer,
                 const LogFusionOptions& options);

}  // namespace navfuse::apps

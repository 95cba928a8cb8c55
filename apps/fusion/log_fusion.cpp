#include "apps/fusion/log_fusion.hpp"

#include <chrono>

#include "apps/common/progress_bar.hpp"
#include "apps/fusion/merger_thread.hpp"
#include "core/geodesy/geoid.hpp"

namespace navfuse::apps {

Summary fuse_log(MeasurementMerger& merger, FusionRunner& runner, FusionObserver& observer,
                 const LogFusionOptions& options) {
  ProgressBar bar(merger.total_bytes(), options.progress_bar);
  ProgressLines lines(merger.total_bytes(), options.progress_lines_label);

  // One-time set-up outside the timed loop: the solution's geoid undulation reads a 4 MB grid
  // on first use, which would otherwise count as processing time in a short replay.
  geo::GeoidGrid::egm96();

  std::uint64_t offered = 0;
  const auto start = std::chrono::steady_clock::now();
  MergerThread reader(merger);
  while (const Measurement* m = reader.next()) {
    runner.offer(*m);
    if ((++offered & 0x3FFF) == 0) {
      bar.update(reader.bytes_read());
      lines.update(reader.bytes_read());
    }
  }
  reader.join();
  runner.finish();
  observer.on_finished();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bar.clear();

  Summary summary;
  summary.inputs = merger.input_summaries();
  runner.fill_summary(summary, wall_s);
  return summary;
}

}  // namespace navfuse::apps

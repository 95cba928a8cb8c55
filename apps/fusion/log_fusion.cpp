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

  // One-time set-up outside the timed loop: the solution's geoid undulation maps its 4 MB grid
  // on first use, which would otherwise count as processing time in a short replay.
  geo::GeoidGrid::egm96();

  std::uint64_t offered = 0;
  const auto start = std::chrono::steady_clock::now();
  MergerThread reader(merger);
  int interrupted_by = 0;
  while (const Measurement* m = reader.next()) {
    runner.offer(*m);
    if ((++offered & 0xFF) == 0 && options.interrupt != nullptr &&
        (interrupted_by = options.interrupt->load(std::memory_order_relaxed)) != 0) {
      break;
    }
    if ((offered & 0x3FFF) == 0) {
      bar.update(reader.bytes_read());
      lines.update(reader.bytes_read());
    }
  }
  if (interrupted_by == 0) {
    reader.join();
  } else {
    reader.stop();  // what it decoded beyond this point stays in the input counters only
  }
  runner.finish();
  observer.on_finished();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bar.clear();

  Summary summary;
  summary.interrupted_by = interrupted_by;
  summary.inputs = merger.input_summaries();
  runner.fill_summary(summary, wall_s);
  return summary;
}

}  // namespace navfuse::apps

// `navfuse bench`: navfuse against the device's own solution in the same log (and both against
// truth when given), with metrics.json, time-series CSVs and report.html in the report folder.
// The command line (bench_command.hpp) is a thin layer over run_bench(), which tests call
// in-process.
//
// Flow: collect (bench_log.hpp: the log through the filter as replay runs it, plus the device's
// solutions and GNSS fix times) -> analyse (bench_analysis.hpp: alignment, errors, statistics,
// phases, start-up timing) -> write metrics.json and CSVs -> render report.html (report.py) ->
// check the --fail-above bounds.
#pragma once

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "apps/bench/fail_threshold.hpp"

namespace navfuse::apps::bench {

struct BenchOptions {
  std::vector<std::string> inputs;
  std::optional<std::int32_t> gps_week;  // --gps-week: the week of imutxt inputs
  std::string config_path;
  std::string truth_path;
  std::string report_dir;
  std::vector<FailThreshold> fail_above;
  std::optional<double> max_gap_s;
  bool allow_truncated = false;
  bool html = true;       // false: metrics.json and CSVs only (no Python needed)
  bool progress = false;  // progress of long logs on stderr
  std::string reference;  // --reference smoothed: also compare both with navfuse's smoothed run
  // Polled while fusing (InterruptSignals::received()): non-zero stops reading; the report
  // covers the part read and BenchResult::interrupted_by says so.
  const std::atomic<int>* interrupt = nullptr;
};

struct BenchResult {
  std::vector<std::string> exceeded;  // --fail-above bounds that were exceeded
  std::vector<std::string> notes;
  std::string summary_text;           // the summary table printed by the command
  std::vector<std::string> warnings;  // most IMU / GNSS samples rejected (rejection_warning.hpp)
  int interrupted_by = 0;             // the signal that stopped the run early (0: ran to the end)
};

// Throws CommandError with a one-line reason on bad input (see collect_bench_log, analyse); exit 2
// when there is nothing to compare; after a signal, exit 128 + signal when what was read holds
// nothing to compare yet.
BenchResult run_bench(const BenchOptions& options);

// Exit status when a --fail-above bound is exceeded (1 is any error).
inline constexpr int kExitThresholdExceeded = 3;

}  // namespace navfuse::apps::bench

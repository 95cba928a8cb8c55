// The comparisons of `navfuse bench` on a collected log: which pairs apply, their aligned errors
// and statistics, the phase timeline, each solution's start-up timing, and the metrics.json
// document (DESIGN.md, contract: one object per pair, named navfuse_vs_device, navfuse_vs_truth,
// device_vs_truth, each with horizontal_m, vertical_m, velocity_mps, roll_deg, pitch_deg,
// heading_deg as {rms, p50, p95, p99, max}, plus samples and overlap_s).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/bench/bench_log.hpp"
#include "apps/bench/pair_comparison.hpp"
#include "apps/bench/phase_timeline.hpp"
#include "apps/bench/solution_timing.hpp"

namespace navfuse::apps::bench {

struct AnalysisOptions {
  std::string truth_path;            // empty: no truth
  std::optional<double> max_gap_s;   // interpolation gap limit; default: 3 median intervals
  // --reference smoothed: navfuse and the device also against BenchLog::smoothed
  // (navfuse_vs_smoothed, device_vs_smoothed), the best reference a log without truth has.
  bool smoothed_reference = false;
};

struct BenchAnalysis {
  PhaseTimeline phases;
  std::vector<PairComparison> pairs;       // in metrics.json order, only those that apply
  SpillFile<TrackSample> truth_at_poses{256};  // truth at navfuse's pose times (for the plots)
  SolutionTiming navfuse_timing;
  std::optional<SolutionTiming> device_timing;
  std::vector<std::string> notes;  // things the reader should know (no device solution...)

  const PairComparison* pair(std::string_view name) const;
  nlohmann::ordered_json metrics_json(const BenchLog& log, const AnalysisOptions& options) const;
};

// Throws CommandError with a one-line reason when a comparison cannot be made: truth on another
// time base than the log, or a pair without any aligned sample (empty overlap).
BenchAnalysis analyse(const BenchLog& log, const AnalysisOptions& options);

}  // namespace navfuse::apps::bench

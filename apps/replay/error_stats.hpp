// Distribution of an error magnitude over a run: RMS, median, 95th / 99th percentile and maximum,
// the figures navfuse reports for accuracy against truth (the same object DESIGN.md defines for
// bench metrics.json: { "rms", "p50", "p95", "p99", "max" }).
//
// Percentiles are nearest-rank (the smallest sample with at least p % of the samples at or
// below it; Hyndman & Fan 1996 definition 1), so every reported figure is an actual sample.
#pragma once

#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

namespace navfuse::apps {

struct ErrorSummary {
  std::size_t samples = 0;
  double rms = 0.0, p50 = 0.0, p95 = 0.0, p99 = 0.0, max = 0.0;
};

class ErrorStats {
 public:
  void add(double error) { values_.push_back(error); }
  std::size_t size() const { return values_.size(); }
  // Sorts a copy; call once at the end.
  ErrorSummary summary() const;

 private:
  std::vector<double> values_;
};

// Nearest-rank percentile of sorted values, p in (0, 100].
double nearest_rank(const std::vector<double>& sorted, double p);

nlohmann::ordered_json to_json(const ErrorSummary& s);

}  // namespace navfuse::apps

// Distribution of an error magnitude over a run: RMS, median, 95th / 99th percentile and maximum,
// the figures navfuse reports for accuracy against truth (the same object DESIGN.md defines for
// bench metrics.json: { "rms", "p50", "p95", "p99", "max" }).
//
// Percentiles are nearest-rank (the smallest sample with at least p % of the samples at or
// below it; Hyndman & Fan 1996 definition 1), so every reported figure is an actual sample.
//
// Memory is constant in the number of samples: the values are sorted externally
// (apps/common/external_sort.hpp, runs spilled to a temporary file), and the summary reads them
// back in ascending order: exact percentiles, and the sum of squares taken in ascending order as
// an in-memory sort would give it, so the figures do not depend on the run length.
#pragma once

#include <cstddef>

#include <nlohmann/json.hpp>

#include "apps/common/external_sort.hpp"

namespace navfuse::apps {

struct ErrorSummary {
  std::size_t samples = 0;
  double rms = 0.0, p50 = 0.0, p95 = 0.0, p99 = 0.0, max = 0.0;
};

class ErrorStats {
 public:
  void add(double error) { values_.add(error); }
  std::size_t size() const { return values_.size(); }
  // One pass over the values in ascending order; call once at the end.
  ErrorSummary summary() const;

 private:
  ExternalSort<double> values_;
};

// The 1-based rank of the nearest-rank p-th percentile of `count` values (count >= 1), p in
// (0, 100].
std::size_t nearest_rank(std::size_t count, double p);

nlohmann::ordered_json to_json(const ErrorSummary& s);

}  // namespace navfuse::apps

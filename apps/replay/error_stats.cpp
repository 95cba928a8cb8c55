#include "apps/replay/error_stats.hpp"

#include <algorithm>
#include <cmath>

namespace navfuse::apps {

double nearest_rank(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0.0;
  const double n = static_cast<double>(sorted.size());
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * n));
  return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

ErrorSummary ErrorStats::summary() const {
  ErrorSummary s;
  s.samples = values_.size();
  if (values_.empty()) return s;
  std::vector<double> sorted = values_;
  std::sort(sorted.begin(), sorted.end());
  double sum_sq = 0.0;
  for (double v : sorted) sum_sq += v * v;
  s.rms = std::sqrt(sum_sq / static_cast<double>(sorted.size()));
  s.p50 = nearest_rank(sorted, 50.0);
  s.p95 = nearest_rank(sorted, 95.0);
  s.p99 = nearest_rank(sorted, 99.0);
  s.max = sorted.back();
  return s;
}

nlohmann::ordered_json to_json(const ErrorSummary& s) {
  return {{"rms", s.rms}, {"p50", s.p50}, {"p95", s.p95}, {"p99", s.p99}, {"max", s.max}};
}

}  // namespace navfuse::apps

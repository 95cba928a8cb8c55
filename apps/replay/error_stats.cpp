#include "apps/replay/error_stats.hpp"

#include <algorithm>
#include <cmath>

namespace navfuse::apps {

std::size_t nearest_rank(std::size_t count, double p) {
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(count)));
  return std::clamp<std::size_t>(rank, 1, count);
}

ErrorSummary ErrorStats::summary() const {
  ErrorSummary s;
  s.samples = values_.size();
  if (values_.empty()) return s;
  // The percentiles are picked at their ranks as the ascending values stream past.
  const std::size_t r50 = nearest_rank(s.samples, 50.0), r95 = nearest_rank(s.samples, 95.0),
                    r99 = nearest_rank(s.samples, 99.0);
  double sum_sq = 0.0;
  std::size_t i = 0;
  auto sorted = values_.sorted();
  for (double v; sorted.next(v);) {
    ++i;
    sum_sq += v * v;
    if (i == r50) s.p50 = v;
    if (i == r95) s.p95 = v;
    if (i == r99) s.p99 = v;
    s.max = v;
  }
  s.rms = std::sqrt(sum_sq / static_cast<double>(s.samples));
  return s;
}

nlohmann::ordered_json to_json(const ErrorSummary& s) {
  return {{"rms", s.rms}, {"p50", s.p50}, {"p95", s.p95}, {"p99", s.p99}, {"max", s.max}};
}

}  // namespace navfuse::apps

#include "apps/run/latency_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace navfuse::apps {
namespace {

// Nearest-rank percentile of a sorted, non-empty sample.
double percentile_us(const std::vector<std::int64_t>& sorted, double p) {
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(sorted.size())));
  const std::size_t index = std::min(sorted.size() - 1, rank > 0 ? rank - 1 : 0);
  return static_cast<double>(sorted[index]) / 1000.0;
}

}  // namespace

LatencyTracker::LatencyTracker(std::size_t capacity) {
  samples_.reserve(std::max<std::size_t>(capacity, 1));
  scratch_.reserve(samples_.capacity());
}

void LatencyTracker::record(std::int64_t latency_ns) {
  std::lock_guard lock(mutex_);
  ++count_;
  if (samples_.size() < samples_.capacity()) {
    samples_.push_back(latency_ns);
  } else {
    samples_[next_] = latency_ns;
    next_ = (next_ + 1) % samples_.size();
  }
}

LatencySummary LatencyTracker::take_window() {
  LatencySummary summary;
  {
    std::lock_guard lock(mutex_);
    summary.samples = count_;
    scratch_.assign(samples_.begin(), samples_.end());
    samples_.clear();
    next_ = 0;
    count_ = 0;
  }
  if (scratch_.empty()) {
    summary.p50_us = summary.p99_us = summary.max_us = std::numeric_limits<double>::quiet_NaN();
    return summary;
  }
  std::sort(scratch_.begin(), scratch_.end());
  summary.p50_us = percentile_us(scratch_, 50.0);
  summary.p99_us = percentile_us(scratch_, 99.0);
  summary.max_us = static_cast<double>(scratch_.back()) / 1000.0;
  return summary;
}

}  // namespace navfuse::apps

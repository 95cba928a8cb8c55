// Latency from IMU sample arrival (its bytes read from the device) to pose publication, for
// NAVFUSE_STATUS (p50/p99). Samples are recorded by the thread that publishes and summarised by
// the status reporter about once a second, over the samples since the previous summary, so the
// figures describe the process now rather than since start-up.
#pragma once

#include <cstdint>
#include <mutex>
#include <vector>

namespace navfuse::apps {

struct LatencySummary {
  std::uint64_t samples = 0;  // 0: nothing published in the window (percentiles are NaN)
  double p50_us = 0.0;
  double p99_us = 0.0;
  double max_us = 0.0;
};

class LatencyTracker {
 public:
  // Keeps at most `capacity` samples per window (older ones in a full window are overwritten, so
  // the window stays a fair sample of the most recent second at any pose rate).
  explicit LatencyTracker(std::size_t capacity = 8192);

  void record(std::int64_t latency_ns);
  // Percentiles of the samples recorded since the previous call; starts a new window.
  LatencySummary take_window();

 private:
  std::mutex mutex_;
  std::vector<std::int64_t> samples_;  // capacity reserved once
  std::size_t next_ = 0;               // overwrite position once full
  std::uint64_t count_ = 0;
  std::vector<std::int64_t> scratch_;  // sorted copy, reused
};

}  // namespace navfuse::apps

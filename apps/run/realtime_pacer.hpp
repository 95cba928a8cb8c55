// `navfuse run --realtime [SPEED]`: file inputs delivered at the pace of their own timestamps
// (SPEED times real time), as the devices that wrote them delivered them. Read as fast as the
// disk allows, a file runs ahead of the filter, and a second file (wheel speeds beside an IMU
// log) ahead of the IMU by minutes: its measurements then overflow the filter's history and are
// rejected (issue 17: 7,903 speeds dropped as overflow where replay uses 7,850).
//
// GPS time is one clock shared by every input; any other base (a device's own running clock) is
// a clock of its input alone. The first measurement seen on a clock pins its time to the host's
// steady clock; each later one waits until (t - t0) / SPEED has passed since.
// A measurement due more than kMaxWaitS ahead (a wild timestamp, a gap in the log) does not
// wait, and its base's clock is pinned again at it, so one bad stamp cannot stall an input.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <map>
#include <optional>
#include <utility>

#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

class RealtimePacer {
 public:
  static constexpr double kMaxWaitS = 5.0;

  explicit RealtimePacer(double speed) : speed_(speed) {}

  // Waits (in steps short enough to notice `stop`) until the measurement is due.
  void wait(const MeasurementHeader& header, const std::atomic<bool>& stop);
  // Measurements that were not waited for because they were due too far ahead.
  std::uint64_t repinned() const { return repinned_.load(std::memory_order_relaxed); }

 private:
  struct Pin {
    std::int64_t data_ns = 0;
    std::int64_t host_ns = 0;
  };
  // The host time `header` is due at, or nullopt when it re-pinned its base.
  std::optional<std::int64_t> due_ns(const MeasurementHeader& header);

  double speed_;
  std::mutex mutex_;
  std::map<std::pair<int, int>, Pin> pins_;  // by (input, time source); input -1 for GPS time
  std::atomic<std::uint64_t> repinned_{0};
};

}  // namespace navfuse::apps

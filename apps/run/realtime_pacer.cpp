#include "apps/run/realtime_pacer.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

#include "apps/run/arrived_measurement.hpp"

namespace navfuse::apps {
namespace {

constexpr std::int64_t kStopCheckNs = 100'000'000;  // how often a waiting input looks at `stop`

}  // namespace

std::optional<std::int64_t> RealtimePacer::due_ns(const MeasurementHeader& header) {
  const std::int64_t now = monotonic_ns();
  std::lock_guard lock(mutex_);
  const int input = header.time_source == TimeSource::kGps ? -1 : header.stream_id;
  const auto [it, first] = pins_.try_emplace({input, static_cast<int>(header.time_source)}, Pin{header.time_ns, now});
  if (first) return now;
  Pin& pin = it->second;
  const double host_offset_ns = static_cast<double>(header.time_ns - pin.data_ns) / speed_;
  const std::int64_t due = pin.host_ns + static_cast<std::int64_t>(host_offset_ns);
  if (static_cast<double>(due - now) > kMaxWaitS * 1e9) {
    pin = Pin{header.time_ns, now};
    repinned_.fetch_add(1, std::memory_order_relaxed);
    return std::nullopt;
  }
  return due;
}

void RealtimePacer::wait(const MeasurementHeader& header, const std::atomic<bool>& stop) {
  const std::optional<std::int64_t> due = due_ns(header);
  if (!due) return;
  for (std::int64_t now = monotonic_ns(); now < *due && !stop.load(std::memory_order_relaxed); now = monotonic_ns()) {
    std::this_thread::sleep_for(std::chrono::nanoseconds(std::min(*due - now, kStopCheckNs)));
  }
}

}  // namespace navfuse::apps

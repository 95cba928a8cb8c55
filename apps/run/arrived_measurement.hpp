// What input readers and aiding receivers hand to the filter thread: the measurement, which
// input it came from, and when its bytes arrived on this host (steady clock), from which the
// nav process measures its latency up to pose publication.
#pragma once

#include <chrono>
#include <cstdint>

#include "apps/run/bounded_queue.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

// Host monotonic time, ns. Steady, not system, clock: latency must not jump with NTP.
inline std::int64_t monotonic_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// Source ids of measurements that did not come from an --in input.
inline constexpr std::uint16_t kSourceLcmAiding = 0xFFFE;
inline constexpr std::uint16_t kSourceOutputCommand = 0xFFFD;  // aiding / sensor inputs on an output link

struct ArrivedMeasurement {
  Measurement measurement;
  std::int64_t arrival_ns = 0;  // monotonic_ns() when the bytes were read
  std::uint16_t source = 0;     // --in index, or one of kSource* above
};

using MeasurementQueue = BoundedQueue<ArrivedMeasurement>;

}  // namespace navfuse::apps

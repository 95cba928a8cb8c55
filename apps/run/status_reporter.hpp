// NAVFUSE_STATUS (about once a second): filter mode and health flags, per-input byte and frame
// rates with bad frames and reconnects, rejections by measurement kind and reason, per-kind
// innovation statistics (updates tried, accepted, rejected, mean NIS, fraction above the gate;
// the non-holonomic constraint's under kind "nhc"), output drops, and the IMU-arrival-to-pose-
// publication latency (p50/p99) over the last interval.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "apps/run/input_reader.hpp"
#include "apps/run/latency_tracker.hpp"
#include "core/measurements/measurements.hpp"
#include "filter/filter_stats.hpp"
#include "navfuse/status_t.hpp"

namespace navfuse::apps {

// innovations[].kind of the non-holonomic constraint (--summary-json: constraints.nhc); the other
// kinds are measurement kinds' names (to_string(MeasurementKind)).
inline constexpr const char* kNhcInnovationKind = "nhc";

struct InputSnapshot {
  std::string name;
  InputCounters counters;
};

// Everything a status message is built from, gathered by the filter thread.
struct StatusInputs {
  const NavSolution& solution;
  const filter::FilterStats& filter;
  const std::vector<InputSnapshot>& inputs;
  std::uint64_t rejected_queue_full = 0;  // measurements lost before the filter (all inputs)
  std::uint64_t rejected_time_base = 0;   // measurements on another clock than the IMU's
  std::uint64_t output_drops = 0;
  LatencySummary latency;
};

class StatusReporter {
 public:
  // Rates are per second over the time since the previous make() (the first call: since start).
  navfuse::status_t make(const StatusInputs& in, std::int64_t now_ns);

 private:
  std::vector<InputCounters> previous_;
  std::int64_t previous_ns_ = 0;
};

}  // namespace navfuse::apps

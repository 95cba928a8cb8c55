// A time span of a scenario (outages, fix-type changes, multipath windows).
#pragma once

namespace navfuse::sim {

// Seconds since the scenario start, half-open [start_s, end_s).
struct TimeInterval {
  double start_s = 0.0;
  double end_s = 0.0;
  bool contains(double t_s) const { return t_s >= start_s && t_s < end_s; }
};

}  // namespace navfuse::sim

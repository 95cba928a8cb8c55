// Multipath jump events (see gnss_multipath.hpp for the model).
#include "apps/sim/gnss_multipath.hpp"

#include <algorithm>
#include <cmath>

#include "apps/sim/random.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {

std::vector<MultipathEvent> multipath_events(const MultipathSpec& spec, std::uint64_t seed) {
  std::vector<MultipathEvent> events;
  if (!(spec.events_per_minute > 0.0) || !(spec.max_offset_m > 0.0)) return events;
  Rng rng(seed, RandomStream::kMultipath);
  const double mean_gap_s = 60.0 / spec.events_per_minute;
  const double lo = std::log(std::max(spec.min_offset_m, 1e-3));
  const double hi = std::log(std::max(spec.max_offset_m, spec.min_offset_m));
  for (const TimeInterval& window : spec.windows) {
    double t = window.start_s;
    for (;;) {
      // Exponential gaps: a Poisson process of the given rate (1 - u is in (0, 1]).
      t += -mean_gap_s * std::log(1.0 - rng.uniform());
      if (t >= window.end_s) break;
      const double duration = spec.min_duration_s + (spec.max_duration_s - spec.min_duration_s) * rng.uniform();
      const double magnitude = std::exp(lo + (hi - lo) * rng.uniform());
      const double azimuth = 2.0 * rot::kPi * rng.uniform();
      const double vertical = spec.vertical_ratio * magnitude * (2.0 * rng.uniform() - 1.0);
      MultipathEvent e;
      e.interval = {t, std::min(t + duration, window.end_s)};
      e.offset_ned_m = {magnitude * std::cos(azimuth), magnitude * std::sin(azimuth), vertical};
      events.push_back(e);
      t = e.interval.end_s;  // the next event starts after this one ends
    }
  }
  std::sort(events.begin(), events.end(), [](const MultipathEvent& a, const MultipathEvent& b) {
    return a.interval.start_s < b.interval.start_s;
  });
  return events;
}

Eigen::Vector3d multipath_offset(const std::vector<MultipathEvent>& events, double t_s, bool* active) {
  // The last event starting at or before t_s is the only one that can contain it (no overlaps).
  const auto it = std::upper_bound(events.begin(), events.end(), t_s,
                                   [](double t, const MultipathEvent& e) { return t < e.interval.start_s; });
  const bool in = it != events.begin() && (it - 1)->interval.contains(t_s);
  if (active) *active = in;
  return in ? (it - 1)->offset_ned_m : Eigen::Vector3d::Zero();
}

}  // namespace navfuse::sim

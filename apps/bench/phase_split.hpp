// Error statistics split by phase (GNSS available / outage, stationary / moving) and by the
// estimate's mode, next to the statistics over the whole overlap: a solution that is better on
// average can still be worse where it matters (dead reckoning through an outage, heading drift
// while stopped), and the split shows it.
#pragma once

#include <array>
#include <optional>

#include <nlohmann/json.hpp>

#include "apps/bench/error_metrics.hpp"
#include "apps/bench/phase_timeline.hpp"

namespace navfuse::apps::bench {

enum class Phase : std::uint8_t { kGnssAvailable = 0, kGnssOutage, kStationary, kMoving, kCount };
inline constexpr std::size_t kPhaseCount = static_cast<std::size_t>(Phase::kCount);
std::string_view phase_key(Phase p);  // "gnss_available", "gnss_outage", "stationary", "moving"

class PhasedMetrics {
 public:
  // `label`: the phase at e.time_ns (nullopt: unknown, counted in the totals only).
  void add(const SolutionError& e, const std::optional<PhaseLabel>& label);

  const MetricSet& all() const { return all_; }
  const MetricSet& phase(Phase p) const { return phases_[static_cast<std::size_t>(p)]; }
  const MetricSet& mode(NavMode m) const { return modes_[static_cast<std::size_t>(m)]; }

  // {"gnss_available": {samples, span_s, horizontal_m: {...}, ...}, ...}: every phase, even empty.
  nlohmann::ordered_json by_phase_json() const;
  // {"navigation": {...}, "dead_reckoning": {...}}: only the modes that occurred.
  nlohmann::ordered_json by_mode_json() const;

 private:
  static constexpr std::size_t kModeCount = static_cast<std::size_t>(NavMode::kSmoothed) + 1;
  MetricSet all_;
  std::array<MetricSet, kPhaseCount> phases_;
  std::array<MetricSet, kModeCount> modes_;
};

}  // namespace navfuse::apps::bench

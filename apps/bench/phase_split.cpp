#include "apps/bench/phase_split.hpp"

#include <string>

namespace navfuse::apps::bench {

std::string_view phase_key(Phase p) {
  switch (p) {
    case Phase::kGnssAvailable: return "gnss_available";
    case Phase::kGnssOutage: return "gnss_outage";
    case Phase::kStationary: return "stationary";
    case Phase::kMoving: return "moving";
    case Phase::kCount: break;
  }
  return "unknown";
}

void PhasedMetrics::add(const SolutionError& e, const std::optional<PhaseLabel>& label) {
  if (!e.any()) return;
  all_.add(e);
  if (label) {
    phases_[static_cast<std::size_t>(label->gnss_outage ? Phase::kGnssOutage : Phase::kGnssAvailable)].add(e);
    phases_[static_cast<std::size_t>(label->stationary ? Phase::kStationary : Phase::kMoving)].add(e);
  }
  const auto m = static_cast<std::size_t>(e.estimate_mode);
  if (m < kModeCount) modes_[m].add(e);
}

nlohmann::ordered_json PhasedMetrics::by_phase_json() const {
  nlohmann::ordered_json j;
  for (std::size_t p = 0; p < kPhaseCount; ++p) j[std::string(phase_key(static_cast<Phase>(p)))] = phases_[p].metrics_json();
  return j;
}

nlohmann::ordered_json PhasedMetrics::by_mode_json() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (std::size_t m = 0; m < kModeCount; ++m) {
    if (modes_[m].samples() > 0) j[std::string(to_string(static_cast<NavMode>(m)))] = modes_[m].metrics_json();
  }
  return j;
}

}  // namespace navfuse::apps::bench

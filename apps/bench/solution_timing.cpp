#include "apps/bench/solution_timing.hpp"

#include <string>

namespace navfuse::apps::bench {

SolutionTiming solution_timing(const SolutionTrack& track, std::int64_t log_start_ns) {
  SolutionTiming t;
  const auto since_start = [&](const TrackSample& s) { return static_cast<double>(s.time_ns - log_start_ns) * 1e-9; };
  std::optional<TrackSample> previous;
  const auto add_mode_time = [&](const TrackSample& s, std::int64_t until_ns) {
    const auto m = static_cast<std::size_t>(s.mode);
    if (m < t.mode_s.size()) t.mode_s[m] += static_cast<double>(until_ns - s.time_ns) * 1e-9;
  };
  SolutionTrack::Reader reader = track.reader();
  for (TrackSample s; reader.next(s);) {
    if (!t.to_attitude_s && has(s, Quantity::kAttitude)) t.to_attitude_s = since_start(s);
    if (!t.to_heading_s && has(s, Quantity::kHeading)) t.to_heading_s = since_start(s);
    if (!t.to_navigation_s && is_navigating(s.mode) && has(s, Quantity::kPosition)) t.to_navigation_s = since_start(s);
    if (previous) add_mode_time(*previous, s.time_ns);
    previous = s;
  }
  return t;
}

nlohmann::ordered_json SolutionTiming::to_json() const {
  const auto value = [](const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(); };
  nlohmann::ordered_json j;
  j["time_to_attitude_s"] = value(to_attitude_s);
  j["time_to_heading_s"] = value(to_heading_s);
  j["time_to_navigation_s"] = value(to_navigation_s);
  nlohmann::ordered_json modes = nlohmann::ordered_json::object();
  for (std::size_t m = 0; m < mode_s.size(); ++m) {
    if (mode_s[m] > 0.0) modes[std::string(to_string(static_cast<NavMode>(m)))] = mode_s[m];
  }
  j["mode_s"] = modes;
  return j;
}

}  // namespace navfuse::apps::bench

// How long each solution took to align, and how long it spent in each mode: the start-up half of
// a benchmark (a filter that is more accurate but navigates a minute later may be the worse one).
//
// Times count from the log's first IMU sample, so navfuse and the device, which both start from
// the same data, are timed from the same instant. A milestone never reached is absent.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

#include "apps/bench/solution_track.hpp"

namespace navfuse::apps::bench {

struct SolutionTiming {
  std::optional<double> to_attitude_s;    // first roll and pitch (levelled)
  std::optional<double> to_heading_s;     // first heading
  std::optional<double> to_navigation_s;  // first full navigation solution with a position
  // Seconds in each mode: each sample's mode holds until the next sample (the last sample has no
  // successor and adds nothing).
  std::array<double, static_cast<std::size_t>(NavMode::kSmoothed) + 1> mode_s{};

  // {"time_to_attitude_s", "time_to_heading_s", "time_to_navigation_s" (null when never),
  //  "mode_s": {"navigation": s, ...} (modes that occurred)}
  nlohmann::ordered_json to_json() const;
};

SolutionTiming solution_timing(const SolutionTrack& track, std::int64_t log_start_ns);

}  // namespace navfuse::apps::bench

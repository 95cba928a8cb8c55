// What the fusion runner (apps/fusion/fusion_runner) hands every output after each IMU sample the
// filter processed: the one record behind every output of `replay`, `bench` and `run` (files,
// device-emulating links, LCM). Each output decides from it what to send when.
#pragma once

#include <cstdint>

#include "core/measurements/measurements.hpp"
#include "filter/solution.hpp"

namespace navfuse::apps {

struct OutputEpoch {
  NavSolution solution;                // the filter's solution at this IMU sample
  // FusionRunner::Solutions::kDeferred: `solution` is left empty and these are what it is
  // computed from, so that the thread that writes the epoch fills it (fill_deferred_solution).
  filter::SolutionInputs solution_inputs{};
  bool solution_deferred = false;
  bool pose_due = false;               // output.rate_hz says a pose goes out at this epoch
  bool gnss_updated = false;           // pose_due, and a GNSS position was fused since the last pose
  std::uint64_t gnss_fused_total = 0;  // running count of fused GNSS positions
  std::uint8_t num_sats = 0;           // of the newest GNSS fix (0: unknown)
  std::int64_t arrival_ns = 0;         // host monotonic time the IMU sample arrived (run; 0 in replay)
  // Running counts of the restarts the filter made on its own (filter::Engine), which a device
  // link announces as it happens.
  std::uint64_t time_gap_restarts = 0;
  std::uint64_t divergence_restarts = 0;

  void fill_deferred_solution() {
    if (!solution_deferred) return;
    filter::fill_nav_solution(solution_inputs, solution);
    solution_deferred = false;
  }
};

}  // namespace navfuse::apps

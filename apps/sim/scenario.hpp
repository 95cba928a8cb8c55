// A complete simulation setup: trajectory, sensors, seed. Plain data that tests copy and modify
// (see scenarios.hpp for the named ones).
#pragma once

#include <cstdint>
#include <string>

#include "apps/sim/gnss_model.hpp"
#include "apps/sim/imu_model.hpp"
#include "apps/sim/trajectory.hpp"
#include "apps/sim/wheel_model.hpp"

namespace navfuse::sim {

inline GnssSpec disabled_gnss() {
  GnssSpec g;
  g.enabled = false;
  return g;
}

struct Scenario {
  std::string name;
  std::uint64_t seed = 1;  // every random draw derives from it: same seed, same output
  // GPS time of t = 0. Default: GPS week 2300, TOW 302400 s (2024-02-07 12:00:00 GPS), a whole
  // second, so that sensor time grids line up with the IMU grid.
  std::int64_t start_time_ns = 2300LL * 604'800LL * 1'000'000'000LL + 302'400LL * 1'000'000'000LL;
  TrajectorySpec trajectory;
  ImuSpec imu;
  GnssSpec gnss;
  // A second receiver with its own antenna (lever_arm_m) and its own noise draws, e.g. the GNSS2
  // fixes of a CV7 or VN-300; off (enabled = false) unless a scenario asks for it.
  GnssSpec second_gnss = disabled_gnss();
  WheelSpec wheel;
};

}  // namespace navfuse::sim

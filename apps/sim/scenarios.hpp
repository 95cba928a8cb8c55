// The named scenarios (`navfuse sim --scenario NAME`, filter accuracy tests). Each returns a fully
// specified Scenario that callers may modify before simulating.
//
//   static_start  60 s standing still (30 s of it the "static start" of every drive), industrial
//                 IMU, 5 Hz standalone GNSS.
//   drive_outage  20-minute drive: 30 s static start, accelerations, turns, stops, a climb, and a
//                 120 s GNSS outage while cruising at 20 m/s; industrial IMU at 200 Hz; 5 Hz
//                 standalone GNSS (1.5 m) with antenna lever arm (0.8, -0.4, -1.3) m; 50 Hz
//                 vehicle speed at the rear axle.
//   rtk_drive     the same drive with 10 Hz RTK-fixed GNSS (2 cm), no outage.
//   drive_short   ~3-minute drive with a 30 s outage (small demo logs), otherwise as drive_outage.
//   delayed_gnss  drive_outage's drive with GNSS delivered 300 ms late (stamps unchanged).
//   outliers      drive_outage's drive with 2 % of fixes displaced 50 m and a 30 m permanent jump
//                 at t = 900 s, no outage.
//   dual_antenna  drive_short with a 1.5 m dual-antenna baseline heading.
//   drive_9min    the first 540 s of the reference drive, GNSS throughout (replay throughput benchmark).
//   drive_8h      the reference drive 24 times over, GNSS throughout: a ~1 GB log for the memory
//                 benchmark of replay and bench (tests/bench/bench_memory.sh).
//   vibration_drive, rtk_fix_changes, urban_multipath, real_drive: real-drive effects, see
//                 reality_scenarios.hpp.
//   calibration_drive  ~3.7 minutes of turns both ways, speed changes, +-8 deg climbs and +-6 deg road
//                 camber (what makes lever arm, mounting and time offset observable) with 10 Hz
//                 RTK-fixed GNSS throughout, the IMU mounted at
//                 roll 0.3, pitch 1.5, yaw -2.0 deg and its clock 50 ms behind GPS time (stamps
//                 early by 50 ms): what `navfuse smooth --calibration-out` recovers.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "apps/sim/scenario.hpp"

namespace navfuse::sim {

// The reference drive's geometry (used by several scenarios).
inline constexpr double kDriveCruiseSpeed_mps = 20.0;
inline constexpr double kDriveOutageStart_s = 600.0;   // in drive_outage: while cruising at 20 m/s
inline constexpr double kDriveOutageDuration_s = 120.0;
inline constexpr double kJumpTime_s = 900.0;           // in outliers

// The 20-minute drive trajectory (starts with 30 s static).
TrajectorySpec reference_drive();
// The ~3-minute drive trajectory (starts with 30 s static).
TrajectorySpec short_drive();

std::vector<std::string_view> scenario_names();
std::optional<Scenario> find_scenario(std::string_view name);
// Throws std::invalid_argument naming the scenario and listing the known ones.
Scenario make_scenario(std::string_view name);

}  // namespace navfuse::sim

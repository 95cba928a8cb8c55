// Scenarios with the effects real drives show and clean simulations lack (issue 14 item 5), each
// a reference-drive scenario of scenarios.hpp plus one effect, and one with all of them:
//
//   vibration_drive  drive_outage (standalone GNSS, wheel speed, 120 s outage) with car engine
//                    and road vibration on the IMU (car_vibration(): 14-42x the data-sheet VRW).
//   rtk_fix_changes  rtk_drive whose receiver drops from RTK fixed to float, DGNSS and standalone
//                    and back (rtk_fix_change_schedule()), each with its reported std devs and
//                    error statistics (receiver_fix_noise()); five float-to-fixed transitions.
//   urban_multipath  rtk_drive with two urban segments (300-500 s, 950-1100 s) of multipath jumps
//                    of 0.2-3 m lasting 1-5 s while the receiver still reports RTK-fixed 2 cm.
//   real_drive       rtk_drive with all three.
//   parking_drive    the held-out car drive of issue 14 as far as it is described: ~9 minutes,
//                    tight car-park corners at 4 m/s and a road stretch, ADIS16465-class IMU at
//                    100 Hz with car vibration, 4 Hz RTK (99.6 % fixed), no wheel speed, IMU
//                    clock 125 ms behind GNSS (stamps late).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "apps/sim/scenario.hpp"

namespace navfuse::sim {

// The fix-type history of rtk_fix_changes: RTK fixed except for these intervals.
std::vector<GnssFixInterval> rtk_fix_change_schedule();
// The urban segments of urban_multipath (seconds since the start).
std::vector<TimeInterval> urban_segments();

// The IMU clock offset of parking_drive (ImuSpec::time_offset_s: stamps 125 ms late).
inline constexpr double kParkingImuTimeOffset_s = -0.125;
Scenario parking_drive();

std::vector<std::string_view> reality_scenario_names();
std::optional<Scenario> find_reality_scenario(std::string_view name);

}  // namespace navfuse::sim

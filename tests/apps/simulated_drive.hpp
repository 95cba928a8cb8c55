// The simulated VN-300 drive the end-to-end replay tests share: scenario drive_short (a 30 s GNSS
// outage at 20 m/s, 95-125 s) written as a VN-300 log `vn.bin`, the odometer as a FusionEngine
// log `wheel_file` and the truth `truth.csv`, all in `dir`. Callers add what differs (tick
// counter, device solution rate) and call run_sim.
#pragma once

#include <filesystem>
#include <string>

#include "apps/simcmd/sim_command.hpp"

namespace navfuse::apps::testing {

inline SimOptions short_drive_sim(const std::filesystem::path& dir, const std::string& wheel_file) {
  SimOptions o;
  o.scenario = "drive_short";
  o.format = "vn";
  o.out_path = (dir / "vn.bin").string();
  o.wheel_out_path = (dir / wheel_file).string();
  o.truth_path = (dir / "truth.csv").string();
  return o;
}

}  // namespace navfuse::apps::testing

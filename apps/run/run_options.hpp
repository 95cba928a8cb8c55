// The command line of `navfuse run` (DESIGN.md, contract: --config F --in URI... [--fe-out URI]
// [--mip-out URI] [--lcm [URL]]), plus the additions this process offers.
#pragma once

#include <string>
#include <vector>

namespace navfuse::apps {

struct RunOptions {
  std::string config_path;
  std::vector<std::string> inputs;  // [FORMAT:]URI
  std::string fe_out;               // URI; empty: none
  std::string mip_out;
  std::string nmea_out;             // URI: NMEA GGA/RMC/HDT (apps/output/nmea_epoch_encoder.hpp)
  std::string csv_out;              // file: the CSV of replay --csv
  bool lcm = false;
  std::string lcm_url;              // empty: LCM's default (LCM_DEFAULT_URL or udpm)
  bool configure_device = false;
  double status_interval_s = 1.0;   // NAVFUSE_STATUS period
  std::string summary_json;         // at exit, the replay-style summary as JSON
  bool quiet = false;               // no summary on stderr at exit
  std::string record_dir;           // --record: raw inputs written here (empty: not recorded)
  int rt_priority = 0;              // --rt-priority: SCHED_FIFO priority (0: normal scheduling)
  bool lock_memory = false;         // --lock-memory: mlockall
  std::string corrections;          // --corrections: ntrip:// or tcp:// source (empty: none)
  int corrections_to = 0;           // --corrections-to: the input (0-based) whose port receives them
  double realtime_speed = 0.0;      // --realtime: file inputs paced at this many times real time (0: not paced)
};

}  // namespace navfuse::apps

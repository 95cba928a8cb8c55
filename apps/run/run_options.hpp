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
};

}  // namespace navfuse::apps

// What the filter thread hands every output link after each IMU sample it processed.
#pragma once

#include <cstdint>

#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

struct OutputEpoch {
  NavSolution solution;
  bool pose_due = false;              // output.rate_hz says a pose goes out at this epoch
  std::uint64_t gnss_fused_total = 0;  // running count of fused GNSS positions
  std::uint8_t num_sats = 0;           // of the newest GNSS fix (0: unknown)
};

}  // namespace navfuse::apps

// The MIP stream of navfuse's solution, one output epoch at a time: the encoder every MIP output
// uses (--mip-out files of replay, the --mip-out device link of run). At each pose epoch the
// filter data set 0x82 a 3DM-CV7 streams (DESIGN.md --mip-out, contract), encoded by the MIP
// front-end (frontends/mip/encoder_solution.hpp); nothing at the other epochs.
#pragma once

#include <cstdint>
#include <vector>

#include "apps/fusion/output_epoch.hpp"

namespace navfuse::apps {

class MipEpochEncoder {
 public:
  // Appends the packets due at `epoch` to `out` (often none).
  void append(const OutputEpoch& epoch, std::vector<std::uint8_t>& out);
};

}  // namespace navfuse::apps

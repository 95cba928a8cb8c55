// One output stream of `navfuse replay` (--fe-out, --mip-out, --csv, --lcm): receives every
// output epoch (apps/fusion/output_epoch.hpp: after each IMU sample the filter processed, with
// whether a pose is due) and writes what its protocol sends at that epoch.
#pragma once

#include "apps/fusion/output_epoch.hpp"

namespace navfuse::apps {

class PoseWriter {
 public:
  virtual ~PoseWriter() = default;
  virtual void write(const OutputEpoch& epoch) = 0;
  // End of a successful run: the output becomes visible under its final name.
  virtual void commit() = 0;
};

}  // namespace navfuse::apps

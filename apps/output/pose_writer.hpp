// One pose output stream of `navfuse replay` / `run` (--fe-out, --mip-out, --csv): receives the
// filter solution after every IMU sample and at the pose output rate, and encodes it in its
// protocol.
#pragma once

#include <cstdint>

#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

// What a writer gets at each pose output time.
struct PoseEpoch {
  const NavSolution& solution;
  bool gnss_updated = false;  // a GNSS position was fused since the previous pose output
  std::uint8_t num_sats = 0;  // satellites of the newest GNSS fix (0: unknown)
};

class PoseWriter {
 public:
  virtual ~PoseWriter() = default;
  // After every IMU sample the filter processed (e.g. FusionEngine IMUOutput at the IMU rate).
  virtual void on_imu(const NavSolution&) {}
  // At output.rate_hz (every IMU sample when it is 0).
  virtual void on_pose(const PoseEpoch& epoch) = 0;
  // End of a successful run: the output becomes visible under its final name.
  virtual void commit() = 0;
};

}  // namespace navfuse::apps

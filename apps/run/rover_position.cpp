#include "apps/run/rover_position.hpp"

#include "apps/output/nmea_epoch_encoder.hpp"

namespace navfuse::apps {

void RoverPosition::update(const OutputEpoch& epoch) {
  // Pose epochs only (output.rate_hz): a caster is told at most every second or so, so copying
  // the solution at every IMU sample would be work for nothing on the filter thread.
  if (!epoch.pose_due || (epoch.solution.header.valid & NavSolution::kValidPosition) == 0) return;
  std::lock_guard lock(mutex_);
  solution_ = epoch.solution;
  num_sats_ = epoch.num_sats;
  known_ = true;
}

bool RoverPosition::append_gga(std::vector<std::uint8_t>& out) const {
  NavSolution s;
  std::uint8_t num_sats = 0;
  {
    std::lock_guard lock(mutex_);
    if (!known_) return false;
    s = solution_;
    num_sats = num_sats_;
  }
  append_gga_sentence(s, num_sats, out);
  return true;
}

}  // namespace navfuse::apps

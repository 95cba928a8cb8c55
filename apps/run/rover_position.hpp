// The rover's position as `navfuse run --corrections ...?gga=S` reports it to a network-RTK
// caster: a VRS mountpoint computes its corrections for where the rover is and sends nothing
// until it has been told (RTCM 10410.1; casters expect an NMEA GGA sentence). The filter thread
// leaves the latest solution with a position here at each pose epoch; the corrections thread
// takes it as a GGA sentence, from the encoder of the --nmea-out link (apps/output/
// nmea_epoch_encoder.hpp), whenever an upload is due.
#pragma once

#include <cstdint>
#include <mutex>
#include <vector>

#include "apps/fusion/output_epoch.hpp"

namespace navfuse::apps {

class RoverPosition {
 public:
  // Filter thread. Only epochs with a position count: once the filter loses its position (a
  // restart) the caster keeps being told the last one, a few metres off at worst, which is
  // far closer than the kilometres a VRS needs (and better than no corrections at all).
  void update(const OutputEpoch& epoch);
  // Any thread: appends the GGA sentence of the latest position (with its CR LF) and returns
  // true; before the filter has had a position, appends nothing and returns false (a caster
  // told nothing waits, which is right: there is nothing true to tell it).
  bool append_gga(std::vector<std::uint8_t>& out) const;

 private:
  mutable std::mutex mutex_;
  bool known_ = false;
  NavSolution solution_;
  std::uint8_t num_sats_ = 0;
};

}  // namespace navfuse::apps

// navfuse's solution as the NMEA 0183 sentences autopilots and generic GNSS consumers read
// (--nmea-out of replay and run): GGA (position, fix quality), RMC (position, speed and course
// over ground, date) and, once the heading is known, HDT (true heading), talker "GN".
//
// Sentences go out at pose epochs (output.rate_hz), at most kNmeaRate_hz: NMEA links are serial
// lines of 9600-115200 baud, where the three sentences (~200 bytes) at 100 Hz would not fit.
// Times are UTC (GPS time less the leap seconds of core/time); a solution not on GPS time has
// empty time and date fields. What the solution does not have is an empty field, and a position
// the filter does not have is GGA quality 0 / RMC status V, as a receiver without a fix writes.
#pragma once

#include <cstdint>
#include <vector>

#include "apps/fusion/output_epoch.hpp"

namespace navfuse::apps {

inline constexpr double kNmeaRate_hz = 10.0;

class NmeaEpochEncoder {
 public:
  // Appends the sentences due at `epoch` (none between the 10 Hz slots).
  void append(const OutputEpoch& epoch, std::vector<std::uint8_t>& out);

 private:
  std::int64_t last_slot_ = INT64_MIN;  // time slot of 1 / kNmeaRate_hz last written
};

// The sentences of one solution, whatever the rate (for tests and the encoder above).
void append_nmea_sentences(const NavSolution& s, std::uint8_t num_sats, std::vector<std::uint8_t>& out);
// Its GGA sentence alone: the rover position an NTRIP client reports to a network-RTK caster
// (apps/run/rover_position.hpp).
void append_gga_sentence(const NavSolution& s, std::uint8_t num_sats, std::vector<std::uint8_t>& out);

}  // namespace navfuse::apps

// Talker identifiers, the two NMEA dialects of the UM220 (CFGNMEA nmeaVer h51 / h30, spec
// L415-L420) and their satellite numbering (h51 GSA L935, h30 GSA L1157, GSV L964 / L1184).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace navfuse::frontends::nmea {

enum class Dialect : std::uint8_t {
  kH51 = 0,  // NMEA 4.1 + BDS: GSA systemID, GSV signalID, RMC navStatus; zero-padded numbers
  kH30 = 1,  // NMEA 3.0 + BDS: no trailing IDs; BDS numbered 161+, Galileo 101+
};

enum class SatSystem : std::uint8_t { kUnknown, kGps, kSbas, kQzss, kGlonass, kGalileo, kBeidou };
std::string_view to_string(SatSystem system);

// Two-letter talker of a sentence name ("GP" of "GPGGA"). Names the UM220 uses: GP (GPS, SBAS,
// QZSS), GB and BD (BDS; h30 tables use both, digest §11 item 20), GA, GL, GN (multi-system).
using Talker = std::array<char, 2>;
SatSystem talker_system(Talker talker);  // kUnknown for GN and unknown talkers

struct SatId {
  SatSystem system = SatSystem::kUnknown;
  std::uint16_t prn = 0;  // the constellation's own PRN / slot number
};

// Satellite number as printed in GSA/GSV -> constellation and PRN. The talker resolves the h51
// numbering, where BDS and Galileo restart at 1; h30 numbers are global (BDS = 160 + PRN,
// Galileo = 100 + PRN, L1157). SBAS 33-64 and QZSS 193+ are global in both.
SatId sat_from_nmea(std::uint32_t number, Talker talker, Dialect dialect);
// Inverse: the number to print for a satellite.
std::uint32_t nmea_from_sat(const SatId& sat, Dialect dialect);

}  // namespace navfuse::frontends::nmea

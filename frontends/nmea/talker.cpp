#include "frontends/nmea/talker.hpp"

namespace navfuse::frontends::nmea {
namespace {

// Number ranges shared by both dialects (L935, L1157).
constexpr std::uint32_t kSbasFirst = 33, kSbasLast = 64;
constexpr std::uint32_t kGlonassFirst = 65, kGlonassLast = 92;
constexpr std::uint32_t kQzssFirst = 193, kQzssLast = 199;
// SBAS numbers are PRN - 87 (NMEA 0183 v4.1 convention: PRN 120 -> 33).
constexpr std::uint32_t kSbasPrnOffset = 87;
constexpr std::uint32_t kGlonassSlotOffset = 64;  // slot 1 -> 65
// h30 global numbering (L1157).
constexpr std::uint32_t kH30GalileoOffset = 100, kH30GalileoLast = 136;
constexpr std::uint32_t kH30BeidouOffset = 160, kH30BeidouLast = 197;

}  // namespace

std::string_view to_string(SatSystem system) {
  switch (system) {
    case SatSystem::kGps: return "gps";
    case SatSystem::kSbas: return "sbas";
    case SatSystem::kQzss: return "qzss";
    case SatSystem::kGlonass: return "glonass";
    case SatSystem::kGalileo: return "galileo";
    case SatSystem::kBeidou: return "beidou";
    case SatSystem::kUnknown: break;
  }
  return "unknown";
}

SatSystem talker_system(Talker t) {
  const auto is = [&](char a, char b) { return t[0] == a && t[1] == b; };
  if (is('G', 'P')) return SatSystem::kGps;
  if (is('G', 'B') || is('B', 'D')) return SatSystem::kBeidou;
  if (is('G', 'A')) return SatSystem::kGalileo;
  if (is('G', 'L')) return SatSystem::kGlonass;
  return SatSystem::kUnknown;
}

SatId sat_from_nmea(std::uint32_t n, Talker talker, Dialect dialect) {
  const auto prn = [](std::uint32_t v) { return static_cast<std::uint16_t>(v); };
  const SatSystem by_talker = talker_system(talker);
  // h51 numbers BDS 1~37 and Galileo 1~36 within their own talker (L935), overlapping SBAS.
  // The GSV table says BDS 01~14 (L964): the wider range is accepted (digest §11 item 16).
  if (dialect == Dialect::kH51 && n >= 1 &&
      (by_talker == SatSystem::kBeidou || by_talker == SatSystem::kGalileo)) {
    return {by_talker, prn(n)};
  }
  if (n >= kSbasFirst && n <= kSbasLast) return {SatSystem::kSbas, prn(n + kSbasPrnOffset)};
  if (n >= kGlonassFirst && n <= kGlonassLast) return {SatSystem::kGlonass, prn(n - kGlonassSlotOffset)};
  if (n >= kQzssFirst && n <= kQzssLast) return {SatSystem::kQzss, prn(n)};
  if (dialect == Dialect::kH30) {
    if (n > kH30BeidouOffset && n <= kH30BeidouLast) return {SatSystem::kBeidou, prn(n - kH30BeidouOffset)};
    if (n > kH30GalileoOffset && n <= kH30GalileoLast) return {SatSystem::kGalileo, prn(n - kH30GalileoOffset)};
  }
  if (n >= 1 && n < kSbasFirst) {
    // GP and GN sentences list GPS as 1..32.
    return {by_talker == SatSystem::kUnknown ? SatSystem::kGps : by_talker, prn(n)};
  }
  return {SatSystem::kUnknown, prn(n)};
}

std::uint32_t nmea_from_sat(const SatId& sat, Dialect dialect) {
  switch (sat.system) {
    case SatSystem::kSbas: return sat.prn - kSbasPrnOffset;
    case SatSystem::kGlonass: return sat.prn + kGlonassSlotOffset;
    case SatSystem::kBeidou: return dialect == Dialect::kH30 ? sat.prn + kH30BeidouOffset : sat.prn;
    case SatSystem::kGalileo: return dialect == Dialect::kH30 ? sat.prn + kH30GalileoOffset : sat.prn;
    default: return sat.prn;
  }
}

}  // namespace navfuse::frontends::nmea

// GPS - UTC offset table. Source: IERS Bulletin C (leap seconds inserted at the end of the day
// before each listed date); GPS - UTC = TAI - UTC - 19 s. Bulletin C 70 (2025) announced no
// leap second through at least mid-2026; extend this table when IERS announces one.
#include "core/time/gps_time.hpp"

#include <array>

namespace navfuse::time {
namespace {

struct LeapEntry {
  std::int64_t unix_s;  // first UTC second (Unix time) at which the new offset applies
  int gps_minus_utc_s;
};

// Dates: 1981-07-01, 1982-07-01, 1983-07-01, 1985-07-01, 1988-01-01, 1990-01-01, 1991-01-01,
// 1992-07-01, 1993-07-01, 1994-07-01, 1996-01-01, 1997-07-01, 1999-01-01, 2006-01-01,
// 2009-01-01, 2012-07-01, 2015-07-01, 2017-01-01.
constexpr std::array<LeapEntry, 18> kLeapTable{{
    {362793600, 1},  {394329600, 2},  {425865600, 3},  {489024000, 4},  {567993600, 5},
    {631152000, 6},  {662688000, 7},  {709948800, 8},  {741484800, 9},  {773020800, 10},
    {820454400, 11}, {867715200, 12}, {915148800, 13}, {1136073600, 14}, {1230768000, 15},
    {1341100800, 16}, {1435708800, 17}, {1483228800, 18},
}};

}  // namespace

int gps_minus_utc_s_at_unix(std::int64_t unix_ns) {
  const std::int64_t s = unix_ns >= 0 ? unix_ns / kNsPerSecond : -((-unix_ns + kNsPerSecond - 1) / kNsPerSecond);
  int offset = 0;
  for (const auto& e : kLeapTable) {
    if (s >= e.unix_s) offset = e.gps_minus_utc_s;
  }
  return offset;
}

int gps_minus_utc_s_at_gps(std::int64_t gps_ns) {
  // A leap second takes effect at GPS time (unix_s - epoch + new offset); compare on the GPS
  // scale so the instant of insertion maps to the new offset exactly.
  const std::int64_t s = gps_ns >= 0 ? gps_ns / kNsPerSecond : -((-gps_ns + kNsPerSecond - 1) / kNsPerSecond);
  int offset = 0;
  for (const auto& e : kLeapTable) {
    if (s >= e.unix_s - kGpsEpochUnixS + e.gps_minus_utc_s) offset = e.gps_minus_utc_s;
  }
  return offset;
}

}  // namespace navfuse::time

// GPS time as integer nanoseconds since the GPS epoch (1980-01-06 00:00:00 UTC), and its
// conversions to GPS week / time of week, UTC (through the leap-second table) and Unix time.
//
// Integer nanoseconds: a double of seconds since 1980 only resolves ~0.1 us, and replay
// determinism wants times that compare and subtract exactly.
#pragma once

#include <cstdint>
#include <optional>

namespace navfuse::time {

inline constexpr std::int64_t kNsPerSecond = 1'000'000'000;
inline constexpr std::int64_t kSecondsPerWeek = 604'800;
inline constexpr std::int64_t kNsPerWeek = kSecondsPerWeek * kNsPerSecond;
// Unix time of the GPS epoch, 1980-01-06T00:00:00Z (IS-GPS-200 §3.3.4; 3657 days after 1970-01-01).
inline constexpr std::int64_t kGpsEpochUnixS = 315'964'800;

struct WeekTow {
  std::int32_t week = 0;  // full (not 10-bit) GPS week number
  double tow_s = 0.0;     // seconds into the week, [0, 604800)
};

// Week + time of week -> ns. TOW outside [0, 604800) is normalised into the week (a receiver that
// reports TOW 604800.0 at the week boundary means week+1, TOW 0). Values beyond int64 ns (about
// +-292 years, or a NaN TOW from a corrupted frame) saturate to the int64 limits rather than
// overflow; decoders reject such times.
std::int64_t gps_ns_from_week_tow(std::int32_t week, double tow_s);
std::int64_t gps_ns_from_week_tow_ns(std::int32_t week, std::int64_t tow_ns);
WeekTow week_tow_from_gps_ns(std::int64_t gps_ns);

// Resolves a 10-bit (mod 1024) week number to the full week closest to `reference_week`
// (IS-GPS-200 §20.3.3.3.1.1: the broadcast WN rolls over every 1024 weeks).
std::int32_t resolve_week_rollover(std::int32_t week_mod_1024, std::int32_t reference_week);

// GPS - UTC in whole seconds at a GPS time (table in leap_seconds.cpp; 18 s since 2017-01-01).
int gps_minus_utc_s_at_gps(std::int64_t gps_ns);
// The same, indexed by a UTC time given as Unix ns.
int gps_minus_utc_s_at_unix(std::int64_t unix_ns);

// UTC given as Unix ns (POSIX time: leap seconds not counted) <-> GPS ns.
std::int64_t gps_ns_from_unix_ns(std::int64_t unix_ns);
std::int64_t unix_ns_from_gps_ns(std::int64_t gps_ns);

struct UtcDateTime {
  int year = 1980, month = 1, day = 6;
  int hour = 0, minute = 0;
  double second = 0.0;  // may reach 60.x only during an inserted leap second
};
// Proleptic Gregorian calendar date -> Unix ns (days-from-civil algorithm, H. Hinnant,
// "chrono-Compatible Low-Level Date Algorithms"). Returns nullopt for an impossible date.
std::optional<std::int64_t> unix_ns_from_utc(const UtcDateTime& utc);
UtcDateTime utc_from_unix_ns(std::int64_t unix_ns);
// UTC date/time (as printed by NMEA ZDA/RMC, Unicore NAVTIME) -> GPS ns, with the table's leap
// seconds, or with `leap_s` when the device states it (Unicore NAVTIME / LSF carry it).
std::optional<std::int64_t> gps_ns_from_utc(const UtcDateTime& utc, std::optional<int> leap_s = {});

inline double seconds(std::int64_t ns) { return static_cast<double>(ns) * 1e-9; }
inline std::int64_t nanoseconds(double s) {
  return static_cast<std::int64_t>(s * 1e9 + (s >= 0 ? 0.5 : -0.5));
}

}  // namespace navfuse::time

#include "core/time/gps_time.hpp"

#include <cmath>
#include <limits>

namespace navfuse::time {
namespace {

// Floor division for possibly negative numerators (C++ '/' truncates toward zero).
constexpr std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

constexpr bool is_leap_year(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }
constexpr int days_in_month(int y, int m) {
  constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return (m == 2 && is_leap_year(y)) ? 29 : kDays[m - 1];
}

// Days since 1970-01-01 of a proleptic Gregorian date (H. Hinnant, "chrono-Compatible Low-Level
// Date Algorithms", days_from_civil): shifts the year to start in March so that the leap day is
// the last day of the shifted year.
constexpr std::int64_t days_from_civil(std::int64_t y, unsigned m, unsigned d) {
  y -= m <= 2;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

// Inverse of days_from_civil (same source, civil_from_days).
constexpr void civil_from_days(std::int64_t z, int& y, int& m, int& d) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const unsigned doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const std::int64_t yy = static_cast<std::int64_t>(yoe) + era * 400;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  y = static_cast<int>(yy + (m <= 2));
}

}  // namespace

std::int64_t gps_ns_from_week_tow_ns(std::int32_t week, std::int64_t tow_ns) {
  // Decoders pass whatever a corrupted frame holds: saturate instead of overflowing (UB).
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  std::int64_t week_ns = 0, sum = 0;
  if (__builtin_mul_overflow(static_cast<std::int64_t>(week), kNsPerWeek, &week_ns)) return week < 0 ? kMin : kMax;
  if (__builtin_add_overflow(week_ns, tow_ns, &sum)) return tow_ns < 0 ? kMin : kMax;
  return sum;
}

std::int64_t gps_ns_from_week_tow(std::int32_t week, double tow_s) {
  // int64 ns spans +-292 years: a TOW outside that (or NaN) saturates, never overflows.
  constexpr double kMaxTowS = 9.0e9;
  if (!(std::abs(tow_s) < kMaxTowS)) {
    return tow_s < 0 ? std::numeric_limits<std::int64_t>::min() : std::numeric_limits<std::int64_t>::max();
  }
  // Split the TOW into whole seconds and a fraction so that the nanoseconds are exact to the
  // double's resolution of the fraction, not of the (up to 6e5) whole value.
  const double whole = std::floor(tow_s);
  const auto frac_ns = static_cast<std::int64_t>(std::llround((tow_s - whole) * 1e9));
  return gps_ns_from_week_tow_ns(week, static_cast<std::int64_t>(whole) * kNsPerSecond + frac_ns);
}

WeekTow week_tow_from_gps_ns(std::int64_t gps_ns) {
  const std::int64_t week = floor_div(gps_ns, kNsPerWeek);
  const std::int64_t tow_ns = gps_ns - week * kNsPerWeek;
  return {static_cast<std::int32_t>(week), static_cast<double>(tow_ns) * 1e-9};
}

std::int32_t resolve_week_rollover(std::int32_t week_mod_1024, std::int32_t reference_week) {
  const std::int32_t wn = ((week_mod_1024 % 1024) + 1024) % 1024;
  // The candidate k*1024 + wn nearest the reference week.
  const std::int32_t base = reference_week - (reference_week % 1024 + 1024) % 1024;
  std::int32_t best = base + wn;
  if (best - reference_week > 512) best -= 1024;
  if (reference_week - best > 512) best += 1024;
  return best;
}

std::int64_t gps_ns_from_unix_ns(std::int64_t unix_ns) {
  return unix_ns - kGpsEpochUnixS * kNsPerSecond +
         static_cast<std::int64_t>(gps_minus_utc_s_at_unix(unix_ns)) * kNsPerSecond;
}

std::int64_t unix_ns_from_gps_ns(std::int64_t gps_ns) {
  return gps_ns + kGpsEpochUnixS * kNsPerSecond -
         static_cast<std::int64_t>(gps_minus_utc_s_at_gps(gps_ns)) * kNsPerSecond;
}

std::optional<std::int64_t> unix_ns_from_utc(const UtcDateTime& utc) {
  if (utc.month < 1 || utc.month > 12 || utc.day < 1 || utc.day > days_in_month(utc.year, utc.month) ||
      utc.hour < 0 || utc.hour > 23 || utc.minute < 0 || utc.minute > 59 || !(utc.second >= 0.0) ||
      utc.second >= 61.0) {
    return std::nullopt;
  }
  const std::int64_t days = days_from_civil(utc.year, static_cast<unsigned>(utc.month),
                                            static_cast<unsigned>(utc.day));
  const std::int64_t whole_s = days * 86400 + utc.hour * 3600 + utc.minute * 60;
  const double sec_floor = std::floor(utc.second);
  const auto frac_ns = static_cast<std::int64_t>(std::llround((utc.second - sec_floor) * 1e9));
  return (whole_s + static_cast<std::int64_t>(sec_floor)) * kNsPerSecond + frac_ns;
}

UtcDateTime utc_from_unix_ns(std::int64_t unix_ns) {
  const std::int64_t days = floor_div(unix_ns, 86400 * kNsPerSecond);
  const std::int64_t ns_of_day = unix_ns - days * 86400 * kNsPerSecond;
  UtcDateTime out;
  civil_from_days(days, out.year, out.month, out.day);
  const std::int64_t s = ns_of_day / kNsPerSecond;
  out.hour = static_cast<int>(s / 3600);
  out.minute = static_cast<int>((s % 3600) / 60);
  out.second = static_cast<double>(s % 60) + static_cast<double>(ns_of_day % kNsPerSecond) * 1e-9;
  return out;
}

std::optional<std::int64_t> gps_ns_from_utc(const UtcDateTime& utc, std::optional<int> leap_s) {
  const auto unix_ns = unix_ns_from_utc(utc);
  if (!unix_ns) return std::nullopt;
  const int leap = leap_s ? *leap_s : gps_minus_utc_s_at_unix(*unix_ns);
  return *unix_ns - kGpsEpochUnixS * kNsPerSecond + static_cast<std::int64_t>(leap) * kNsPerSecond;
}

}  // namespace navfuse::time

#include "frontends/nmea/utc_fields.hpp"

#include <cmath>

#include "core/time/gps_time.hpp"
#include "frontends/nmea/fields.hpp"

namespace navfuse::frontends::nmea {
namespace {

constexpr std::size_t kHhmmssDigits = 6;
constexpr std::size_t kDdmmyyDigits = 6;
constexpr int kCenturyBase = 2000;
constexpr int kMaxDecimals = 9;  // nanoseconds

bool two_digits(std::string_view s, std::size_t at, int& out) {
  const char a = s[at], b = s[at + 1];
  if (a < '0' || a > '9' || b < '0' || b > '9') return false;
  out = (a - '0') * 10 + (b - '0');
  return true;
}

}  // namespace

std::optional<TimeOfDay> parse_time_of_day(std::string_view field) {
  if (field.size() < kHhmmssDigits) return std::nullopt;
  int hh = 0, mm = 0, ss = 0;
  if (!two_digits(field, 0, hh) || !two_digits(field, 2, mm) || !two_digits(field, 4, ss)) {
    return std::nullopt;
  }
  if (hh > 23 || mm > 59 || ss > 60) return std::nullopt;
  std::int64_t frac_ns = 0;
  int decimals = 0;
  if (field.size() > kHhmmssDigits) {
    if (field[kHhmmssDigits] != '.') return std::nullopt;
    const std::string_view frac = field.substr(kHhmmssDigits + 1);
    if (frac.size() > static_cast<std::size_t>(kMaxDecimals)) return std::nullopt;
    std::int64_t scale = time::kNsPerSecond;
    for (char c : frac) {
      if (c < '0' || c > '9') return std::nullopt;
      scale /= 10;
      frac_ns += (c - '0') * scale;
    }
    decimals = static_cast<int>(frac.size());
  }
  const std::int64_t seconds = (hh * 60 + mm) * 60 + ss;
  return TimeOfDay{seconds * time::kNsPerSecond + frac_ns, decimals};
}

std::optional<Date> parse_date_ddmmyy(std::string_view field) {
  if (field.size() != kDdmmyyDigits) return std::nullopt;
  int dd = 0, mm = 0, yy = 0;
  if (!two_digits(field, 0, dd) || !two_digits(field, 2, mm) || !two_digits(field, 4, yy)) {
    return std::nullopt;
  }
  const Date date{kCenturyBase + yy, mm, dd};
  // Let the core calendar reject 31 April and 29 February of common years.
  if (!time::unix_ns_from_utc(time::UtcDateTime{date.year, date.month, date.day, 0, 0, 0.0})) {
    return std::nullopt;
  }
  return date;
}

void add_time_of_day(SentenceWriter& w, const TimeOfDay& t) {
  const int decimals = t.decimals < 0 ? 0 : (t.decimals > kMaxDecimals ? kMaxDecimals : t.decimals);
  std::int64_t unit = time::kNsPerSecond;
  for (int i = 0; i < decimals; ++i) unit /= 10;
  // Round to the printed resolution once, in integers, so that 59.999 never prints as 60.00.
  std::int64_t ns = (t.ns + unit / 2) / unit * unit;
  const std::int64_t total_s = ns / time::kNsPerSecond;
  const std::int64_t frac_units = (ns % time::kNsPerSecond) / unit;
  const std::int64_t hh = total_s / 3600, mm = total_s / 60 % 60, ss = total_s % 60;
  w.add_uint(static_cast<std::uint64_t>(hh), 2);
  w.append_uint(static_cast<std::uint64_t>(mm), 2);
  w.append_uint(static_cast<std::uint64_t>(ss), 2);
  if (decimals > 0) {
    w.append(".");
    w.append_uint(static_cast<std::uint64_t>(frac_units), decimals);
  }
}

void add_date_ddmmyy(SentenceWriter& w, const Date& d) {
  w.add_uint(static_cast<std::uint64_t>(d.day), 2);
  w.append_uint(static_cast<std::uint64_t>(d.month), 2);
  w.append_uint(static_cast<std::uint64_t>(((d.year % 100) + 100) % 100), 2);
}

}  // namespace navfuse::frontends::nmea

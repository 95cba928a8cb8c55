// UTC time-of-day ("hhmmss.ss[s]") and date ("ddmmyy") fields of NMEA and Unicore sentences
// (GGA L875, RMC L989-L999, GYOACC L741-L745), kept with their printed decimals.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "frontends/nmea/writer.hpp"

namespace navfuse::frontends::nmea {

inline constexpr std::int64_t kNsPerDay = 86'400'000'000'000;

struct TimeOfDay {
  std::int64_t ns = 0;  // since 00:00:00 UTC; a leap second (60.x) reaches past 86400 s
  int decimals = 2;     // printed decimals of the seconds
};

struct Date {
  int year = 2000;  // full year; "yy" is read as 20yy (the receivers postdate 2000)
  int month = 1;
  int day = 1;
};

// "hhmmss" with optional fraction; nullopt for empty or malformed fields or hh > 23, mm > 59,
// ss > 60.
std::optional<TimeOfDay> parse_time_of_day(std::string_view field);
// "ddmmyy"; nullopt for empty or impossible dates.
std::optional<Date> parse_date_ddmmyy(std::string_view field);

void add_time_of_day(SentenceWriter& w, const TimeOfDay& t);
void add_date_ddmmyy(SentenceWriter& w, const Date& d);

}  // namespace navfuse::frontends::nmea

// GPS time conversions against published instants: the GPS epoch (IS-GPS-200 §3.3.4), the
// 2017-01-01 leap second (IERS Bulletin C 52: GPS-UTC becomes 18 s), the week 1024 and 2048
// rollovers (1999-08-22 and 2019-04-07, GPS time).
#include "core/time/gps_time.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace navfuse::time {
namespace {

constexpr std::int64_t kS = kNsPerSecond;

TEST(GpsTime, EpochIsUnix315964800) {
  EXPECT_EQ(gps_ns_from_unix_ns(kGpsEpochUnixS * kS), 0);
  EXPECT_EQ(unix_ns_from_gps_ns(0), kGpsEpochUnixS * kS);
  const auto utc = utc_from_unix_ns(kGpsEpochUnixS * kS);
  EXPECT_EQ(utc.year, 1980);
  EXPECT_EQ(utc.month, 1);
  EXPECT_EQ(utc.day, 6);
}

TEST(GpsTime, LeapSecondBoundary2017) {
  // 2017-01-01T00:00:00Z = Unix 1483228800; GPS = 1483228800 - 315964800 + 18 = 1167264018.
  EXPECT_EQ(gps_minus_utc_s_at_unix(1483228800 * kS), 18);
  EXPECT_EQ(gps_minus_utc_s_at_unix(1483228800 * kS - 1), 17);
  EXPECT_EQ(gps_ns_from_unix_ns(1483228800 * kS), 1167264018 * kS);
  // One second before midnight UTC is 17 s offset: GPS 1167264016.
  EXPECT_EQ(gps_ns_from_unix_ns(1483228799 * kS), 1167264016 * kS);
  // GPS 1167264017 is the inserted 23:59:60; from 1167264018 on the offset is 18.
  EXPECT_EQ(gps_minus_utc_s_at_gps(1167264018 * kS), 18);
  EXPECT_EQ(gps_minus_utc_s_at_gps(1167264017 * kS), 17);
  EXPECT_EQ(unix_ns_from_gps_ns(1167264018 * kS), 1483228800 * kS);
}

TEST(GpsTime, EveryLeapSecondRoundTripsAwayFromTheBoundary) {
  // 1 h either side of each table entry, UTC -> GPS -> UTC is the identity.
  for (std::int64_t unix_s : {362793600LL, 567993600LL, 915148800LL, 1136073600LL, 1230768000LL,
                              1341100800LL, 1435708800LL, 1483228800LL}) {
    for (std::int64_t d : {-3600LL, 3600LL}) {
      const std::int64_t u = (unix_s + d) * kS + 123456789;
      EXPECT_EQ(unix_ns_from_gps_ns(gps_ns_from_unix_ns(u)), u) << unix_s;
    }
  }
}

TEST(GpsTime, UtcCalendarToGps) {
  // Week 2048 began 2019-04-07T00:00:00 GPS = 2019-04-06T23:59:42 UTC (GPS-UTC = 18 s).
  const auto gps = gps_ns_from_utc({2019, 4, 6, 23, 59, 42.0});
  ASSERT_TRUE(gps.has_value());
  const auto wt = week_tow_from_gps_ns(*gps);
  EXPECT_EQ(wt.week, 2048);
  EXPECT_DOUBLE_EQ(wt.tow_s, 0.0);
  // A device stating its own leap seconds is believed.
  EXPECT_EQ(*gps_ns_from_utc({2019, 4, 6, 23, 59, 43.0}, 17), *gps);
  // Impossible dates are rejected.
  EXPECT_FALSE(gps_ns_from_utc({2023, 2, 29, 0, 0, 0.0}).has_value());
  EXPECT_TRUE(gps_ns_from_utc({2024, 2, 29, 0, 0, 0.0}).has_value());
  EXPECT_FALSE(gps_ns_from_utc({2024, 13, 1, 0, 0, 0.0}).has_value());
  EXPECT_FALSE(gps_ns_from_utc({2024, 1, 1, 24, 0, 0.0}).has_value());
}

TEST(GpsTime, WeekRolloverDates) {
  // Week 1024 started 1999-08-22 (GPS); in UTC that is 1999-08-21T23:59:47 (13 leap s).
  EXPECT_EQ(week_tow_from_gps_ns(*gps_ns_from_utc({1999, 8, 21, 23, 59, 47.0})).week, 1024);
  EXPECT_EQ(resolve_week_rollover(0, 2048), 2048);
  EXPECT_EQ(resolve_week_rollover(1023, 2048), 2047);
  EXPECT_EQ(resolve_week_rollover(5, 2300), 2053);
  EXPECT_EQ(resolve_week_rollover(1000, 2060), 2024);
  EXPECT_EQ(resolve_week_rollover(300, 2350), 2348);
}

TEST(GpsTime, TowWrapsIntoTheNextWeek) {
  const auto wt = week_tow_from_gps_ns(gps_ns_from_week_tow(2100, 604800.0));
  EXPECT_EQ(wt.week, 2101);
  EXPECT_DOUBLE_EQ(wt.tow_s, 0.0);
  const auto back = week_tow_from_gps_ns(gps_ns_from_week_tow(2100, -0.5));
  EXPECT_EQ(back.week, 2099);
  EXPECT_DOUBLE_EQ(back.tow_s, 604799.5);
  // Sub-microsecond TOW survives (the fraction is converted separately from the whole seconds).
  EXPECT_EQ(gps_ns_from_week_tow(2200, 345600.000000123) - gps_ns_from_week_tow_ns(2200, 345600 * kS), 123);
}

TEST(GpsTime, AbsurdWeekOrTowSaturatesInsteadOfOverflowing) {
  // Found by the Unicore fuzzer: a corrupted TOW of 4.6e10 s overflowed int64 ns (UB).
  constexpr auto kMax = std::numeric_limits<std::int64_t>::max();
  constexpr auto kMin = std::numeric_limits<std::int64_t>::min();
  EXPECT_EQ(gps_ns_from_week_tow(2300, 46081800000.0), kMax);
  EXPECT_EQ(gps_ns_from_week_tow(2300, -46081800000.0), kMin);
  EXPECT_EQ(gps_ns_from_week_tow(2300, std::nan("")), kMax);
  EXPECT_EQ(gps_ns_from_week_tow_ns(2'000'000'000, 0), kMax);
  EXPECT_EQ(gps_ns_from_week_tow_ns(-2'000'000'000, 0), kMin);
  EXPECT_EQ(gps_ns_from_week_tow_ns(15000, kMax), kMax);
}

TEST(GpsTime, CalendarRoundTripOverCenturies) {
  for (std::int64_t unix_s = -2208988800LL; unix_s < 4102444800LL; unix_s += 86400LL * 97 + 3601) {
    const auto utc = utc_from_unix_ns(unix_s * kS);
    EXPECT_EQ(*unix_ns_from_utc(utc), unix_s * kS);
  }
}

}  // namespace
}  // namespace navfuse::time

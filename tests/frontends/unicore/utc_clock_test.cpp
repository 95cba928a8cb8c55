// UtcClock: UTC stamps of the UM220 onto GPS time (leap seconds, day and week rollover).
#include <gtest/gtest.h>

#include "core/time/gps_time.hpp"
#include "frontends/unicore/utc_clock.hpp"

namespace navfuse::frontends::unicore {
namespace {

constexpr std::int64_t kS = 1'000'000'000;

nmea::TimeOfDay tod(int h, int m, double s) {
  return {(h * 3600LL + m * 60LL) * kS + static_cast<std::int64_t>(s * 1e9 + 0.5), 3};
}

TEST(UtcClock, TimeOfDayNeedsADateFirst) {
  UtcClock c;
  EXPECT_FALSE(c.from_time_of_day(tod(6, 8, 45)));
  EXPECT_FALSE(c.from_ms_of_week(1000, 1));
  // 2017-08-18 06:08:45 UTC (RMC/ZDA example L982/L1039), 18 leap seconds since 2017-01-01.
  const auto t = c.from_utc({2017, 8, 18}, tod(6, 8, 45));
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, *time::gps_ns_from_utc({2017, 8, 18, 6, 8, 45.0}));
  EXPECT_EQ(*t, time::gps_ns_from_unix_ns(*time::unix_ns_from_utc({2017, 8, 18, 6, 8, 45.0})));
  const auto later = c.from_time_of_day(tod(6, 8, 46.5));
  ASSERT_TRUE(later);
  EXPECT_EQ(*later - *t, 1'500'000'000);
}

TEST(UtcClock, MidnightRolloverPicksTheNextDay) {
  UtcClock c;
  const auto before = c.from_utc({2019, 12, 31}, tod(23, 59, 59.9));
  const auto after = c.from_time_of_day(tod(0, 0, 0.1));
  ASSERT_TRUE(before && after);
  EXPECT_EQ(*after - *before, 200'000'000);
  // A late sentence from before midnight still resolves to the old day.
  const auto late = c.from_time_of_day(tod(23, 59, 59.8));
  EXPECT_EQ(*before - *late, 100'000'000);
}

TEST(UtcClock, MsOfWeekNearestTheAnchorAndBdsOffset) {
  UtcClock c;
  Navtime nt;  // NAVTIME example L1325: week 2050, 99974.000222664 s
  nt.gps_week = 2050;
  nt.gps_tow_s = {99974.000222664, 9};
  nt.gps_quality = 3;
  const auto anchor = c.on_navtime(nt);
  ASSERT_TRUE(anchor);
  const auto gps = c.from_ms_of_week(99975000, 0x1);  // GPS in the mask
  EXPECT_EQ(*gps, time::gps_ns_from_week_tow(2050, 99975.0));
  // BDS only (bit2): BDT + 14 s = GPST.
  const auto bds = c.from_ms_of_week(99961000, 0x4);
  EXPECT_EQ(*bds, time::gps_ns_from_week_tow(2050, 99975.0));
  EXPECT_FALSE(c.from_ms_of_week(99961000, 0x10));  // GLONASS only
  // Week rollover: a time of week just after 0 near the end of the week goes to the next week.
  UtcClock d;
  Navtime end = nt;
  end.gps_tow_s = {604799.5, 1};
  d.on_navtime(end);
  EXPECT_EQ(*d.from_ms_of_week(500, 0x1), time::gps_ns_from_week_tow(2051, 0.5));
}

TEST(UtcClock, LeapSecondsFromNavtimeGlonassTime) {
  UtcClock c;
  Navtime nt;
  nt.gps_week = 2050;
  nt.gps_tow_s = {99974.000222664, 9};
  nt.gps_quality = 3;
  nt.glo_time_of_day_s = {24356.000222657, 9};  // Moscow time = UTC + 3 h
  nt.glo_quality = 3;
  c.on_navtime(nt);
  EXPECT_TRUE(c.leap_from_device());
  EXPECT_EQ(c.gps_minus_utc_s(0), 18);  // device value, whatever the table says at epoch 0
}

TEST(UtcClock, LsfAnnouncedLeapSecondTakesEffectAfterDayDn) {
  UtcClock c;
  // The 2016-12-31 leap second as LSF would announce it: GPS week 1929 (Sunday 2016-12-25 to
  // Saturday 2016-12-31) broadcast as 1929 mod 256, DN = 7 (Saturday, L1436), 17 -> 18 s.
  ASSERT_TRUE(c.from_utc({2016, 12, 28}, tod(12, 0, 0)));
  Lsf lsf;
  lsf.system = 0;
  lsf.flag = 1;
  lsf.tls_s = 17;
  lsf.tlsf_s = 18;
  lsf.wnlsf = 1929 % 256;
  lsf.dn = 7;
  c.on_lsf(lsf);
  const std::int64_t before = time::gps_ns_from_week_tow(1929, 6 * 86400.0 + 3600.0);  // Saturday
  const std::int64_t after = time::gps_ns_from_week_tow(1930, 3600.0);                 // Sunday
  EXPECT_EQ(c.gps_minus_utc_s(before), 17);
  EXPECT_EQ(c.gps_minus_utc_s(after), 18);
}

}  // namespace
}  // namespace navfuse::frontends::unicore

// Every checksummed UM220 output example of digest §10.1 decodes to the printed values and
// re-encodes to the same bytes; the three the digest shows to be wrong fail their checksum.
// NAVPOS and NAVTIME are cross-checked as coordinate and time conversions.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/unicore/messages.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::unicore {
namespace {

using test::frame;
using test::reencode;

const std::string kGyoacc =  // L736
    "$GYOACC,081118,053152.000,0.017618,0.031686,0.019729,200,6.489322,-6.913150,2.960812,200,0,5,200,1*2C";

TEST(UnicoreExamples, Gyoacc) {
  const auto fr = frame(kGyoacc);
  ASSERT_TRUE(fr);
  const auto m = decode_gyoacc(fr->fields, false);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->date->year, 2018);
  EXPECT_EQ(m->date->month, 11);
  EXPECT_EQ(m->date->day, 8);  // ddmmyy, not "ddmmmyy" (digest §11 item 12)
  EXPECT_EQ(m->time->ns, ((5 * 60 + 31) * 60 + 52) * 1'000'000'000LL);
  EXPECT_DOUBLE_EQ(m->gyro_rps[0]->value, 0.017618);
  EXPECT_DOUBLE_EQ(m->gyro_rps[1]->value, 0.031686);
  EXPECT_DOUBLE_EQ(m->gyro_rps[2]->value, 0.019729);
  EXPECT_EQ(m->gyro_period_ms, 200u);
  EXPECT_DOUBLE_EQ(m->accel_mps2[0]->value, 6.489322);
  EXPECT_DOUBLE_EQ(m->accel_mps2[1]->value, -6.913150);
  EXPECT_DOUBLE_EQ(m->accel_mps2[2]->value, 2.960812);
  EXPECT_EQ(m->accel_period_ms, 200u);
  EXPECT_EQ(m->temperature_c, 0);
  EXPECT_EQ(m->pulses, 5u);
  EXPECT_EQ(m->pulse_period_ms, 200u);
  EXPECT_EQ(m->reverse, 1u);
  EXPECT_EQ(reencode(*m), kGyoacc);
}

TEST(UnicoreExamples, GyoaccVPrintedChecksumIsWrong) {
  // L770 printed with GYOACC's checksum 2C; the text's XOR is 57 (digest §10.1, §11 item 14).
  const std::string body =
      "$GYOACC-V,081118,053152.000,0.017618,0.031686,0.019729,200,6.489322,-6.913150,2.960812,200,0,5,200,1";
  EXPECT_FALSE(frame(body + "*2C"));
  const auto fr = frame(body + "*57");
  ASSERT_TRUE(fr);
  const auto m = decode_gyoacc(fr->fields, true);
  ASSERT_TRUE(m);
  EXPECT_TRUE(m->vehicle_frame);
  EXPECT_EQ(reencode(*m), body + "*57");
  // Before alignment the IMU fields are null (L771): still a valid sentence.
  const std::string unaligned = "GYOACC-V,081118,053152.000,,,,200,,,,200,0,5,200,0";
  nmea::Fields f;
  f.split(unaligned);
  const auto u = decode_gyoacc(f, true);
  ASSERT_TRUE(u);
  EXPECT_FALSE(u->gyro_rps[0]);
  EXPECT_FALSE(u->accel_mps2[2]);
}

TEST(UnicoreExamples, Snrstat) {
  const std::string s = "$SNRSTAT,3,0,0,2*5C";  // L810
  const auto m = decode_snrstat(frame(s)->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->ins_status, 3);
  EXPECT_EQ(m->odo_status, 0);
  EXPECT_EQ(m->install_state, 0);
  EXPECT_EQ(*m->map_status, 2);
  EXPECT_EQ(reencode(*m), s);
}

TEST(UnicoreExamples, MapfbWithTheSpaceInsideTheChecksum) {
  // L828: the space after "MAPFB," is part of the checksummed text (digest §10.1).
  EXPECT_TRUE(frame("$MAPFB, 082324.000,3,1,1,520,15,-4,0,4,4945*78"));
  EXPECT_TRUE(frame("$MAPFB, 082324.000,3,2,1,320,25,8,0,3,4745*56"));
  EXPECT_TRUE(frame("$MAPFB, 082324.000,3,3,1,160,-17,-4,0,8,4645*56"));
  EXPECT_FALSE(frame("$MAPFB,082324.000,3,1,1,520,15,-4,0,4,4945*78"));
}

TEST(UnicoreExamples, NavposAndItsGeodesy) {
  const std::string s =  // L1282, wrap spaces removed
      "$NAVPOS,282201000,5,3,-2160481.168,4383619.182,4084735.203,40.078998,116.236534,52.843847*1C";
  const auto m = decode_navpos(frame(s)->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->time_ms, 282201000u);
  EXPECT_EQ(m->system, 5u);  // GPS + BDS
  EXPECT_EQ(m->quality, 3u);
  EXPECT_DOUBLE_EQ(m->ecef_m[0].value, -2160481.168);
  EXPECT_DOUBLE_EQ(m->lat_deg.value, 40.078998);
  EXPECT_DOUBLE_EQ(m->height_m.value, 52.843847);
  EXPECT_EQ(reencode(*m), s);
  // The ECEF and geodetic fields describe the same point on WGS-84 (digest §4.5: recomputed
  // 40.0789990 deg, 116.2365349 deg, 52.843 m; the printed degrees look truncated to 1e-6).
  const geo::Llh llh = geo::llh_from_ecef({m->ecef_m[0].value, m->ecef_m[1].value, m->ecef_m[2].value});
  EXPECT_NEAR(llh.lat_rad * rot::kRadToDeg, m->lat_deg.value, 1.5e-6);
  EXPECT_NEAR(llh.lon_rad * rot::kRadToDeg, m->lon_deg.value, 1.5e-6);
  EXPECT_NEAR(llh.height_m, m->height_m.value, 0.01);
  // Read as ms of week, 282201000 is day 3 (Wednesday, Sunday = 0) at 06:23:21 (digest §4.5).
  EXPECT_EQ(m->time_ms / 86'400'000u, 3u);
  EXPECT_EQ(m->time_ms % 86'400'000u, ((6u * 60 + 23) * 60 + 21) * 1000u);
}

TEST(UnicoreExamples, Navvel) {
  const std::string s = "$NAVVEL,282201000,5,3,0.000,0.000,0.000,31.785*2F";  // L1305
  const auto m = decode_navvel(frame(s)->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->time_ms, 282201000u);
  EXPECT_DOUBLE_EQ(m->vel_ecef_mps[2].value, 0.0);
  EXPECT_DOUBLE_EQ(m->clock_drift_mps.value, 31.785);
  EXPECT_EQ(reencode(*m), s);
}

TEST(UnicoreExamples, NavtimeAndItsTimeScales) {
  const std::string s =  // L1325
      "$NAVTIME,2050,99974.000222664,3,694,99960.000222685,3,1026,99974.000222660,3,6,1208,24356.000222657,0*65";
  const auto m = decode_navtime(frame(s)->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->gps_week, 2050u);
  EXPECT_DOUBLE_EQ(m->gps_tow_s.value, 99974.000222664);
  EXPECT_EQ(m->gps_quality, 3u);
  EXPECT_EQ(m->glo_four_year, 6u);
  EXPECT_EQ(m->glo_day, 1208u);
  EXPECT_EQ(m->glo_quality, 0u);
  EXPECT_EQ(reencode(*m), s);
  // GPS week 2050 + 99974 s is 2019-04-22 03:46:14 GPST = 03:45:56 UTC (GPS - UTC = 18 s).
  const std::int64_t gps_ns = time::gps_ns_from_week_tow(2050, m->gps_tow_s.value);
  const time::UtcDateTime utc = time::utc_from_unix_ns(time::unix_ns_from_gps_ns(gps_ns));
  EXPECT_EQ(utc.year, 2019);
  EXPECT_EQ(utc.month, 4);
  EXPECT_EQ(utc.day, 22);
  EXPECT_EQ(utc.hour, 3);
  EXPECT_EQ(utc.minute, 45);
  EXPECT_NEAR(utc.second, 56.000222664, 1e-6);
  // Independent scales: BDT = GPST - 14 s in week GPS - 1356; GST = GPST in week GPS - 1024;
  // GLONASS = UTC + 3 h, day 1208 of the 4-year interval starting 2016-01-01.
  EXPECT_EQ(m->bds_week + 1356, m->gps_week);
  EXPECT_NEAR(m->bds_tow_s.value + 14.0, m->gps_tow_s.value, 1e-6);
  EXPECT_EQ(m->gal_week + 1024, m->gps_week);
  EXPECT_NEAR(m->glo_time_of_day_s.value - 3 * 3600.0, ((3 * 60 + 45) * 60 + 56.000222664), 1e-6);
  const auto interval_start = time::unix_ns_from_utc({2016, 1, 1, 0, 0, 0.0});
  const auto day = time::unix_ns_from_utc({2019, 4, 22, 0, 0, 0.0});
  EXPECT_EQ((*day - *interval_start) / 86'400'000'000'000LL + 1, 1208);
}

TEST(UnicoreExamples, NavaccPrintedChecksumIsWrong) {
  // L1353: printed 7D, the text's XOR is 5D (digest §11 item 25).
  EXPECT_FALSE(frame("$NAVACC,085206.00,A,2480,70,1250*7D"));
  const std::string fixed = "$NAVACC,085206.00,A,2480,70,1250*5D";
  const auto m = decode_navacc(frame(fixed)->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->status, 'A');
  EXPECT_EQ(m->pos_acc_mm, 2480u);  // 2.480 m
  EXPECT_EQ(m->vel_acc_mmps, 70u);
  EXPECT_EQ(m->course_acc_mdeg, 1250u);
  EXPECT_EQ(reencode(*m), fixed);
}

TEST(UnicoreExamples, Navatt) {
  const std::string s = "$NAVATT,060917.00,7,-168753,114146,159559,15459,16206,19998*17";  // L1371
  const auto m = decode_navatt(frame(s)->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->quality, 7u);
  EXPECT_EQ(m->roll_e5deg, -168753);   // -1.68753 deg
  EXPECT_EQ(m->pitch_e5deg, 114146);
  EXPECT_EQ(m->yaw_e5deg, 159559);
  EXPECT_EQ(m->yaw_std_e5deg, 19998u);
  EXPECT_EQ(reencode(*m), s);
}

TEST(UnicoreExamples, NoticeLsfCwout) {
  const std::string notice = "$NOTICE,1,10000,10000,10000,20,0,FFFF,FFFF,FFFF,1000*29";  // L1457
  const auto fr = frame(notice);
  ASSERT_TRUE(fr);
  const auto n = decode_notice(fr->fields);
  ASSERT_TRUE(n);
  EXPECT_EQ(n->count, 10u);
  EXPECT_EQ(n->fields[6], "FFFF");
  EXPECT_EQ(reencode(*n), notice);
  // LSF and CWOUT are printed without checksum (L1407, L1445): decode them as such.
  const auto lsf = decode_lsf(frame("$LSF,0,1,15,16,462836,82,6,86,7811626,14")->fields);
  ASSERT_TRUE(lsf);
  EXPECT_EQ(lsf->tls_s, 15u);
  EXPECT_EQ(lsf->tlsf_s, 16u);
  EXPECT_EQ(lsf->wnlsf, 86u);
  EXPECT_EQ(lsf->a0, 7811626);
  EXPECT_EQ(reencode(*lsf), "$LSF,0,1,15,16,462836,82,6,86,7811626,14*5C");  // digest §10.2
  const auto cw = decode_cwout(frame("$CWOUT,1,0")->fields);
  ASSERT_TRUE(cw);
  EXPECT_EQ(cw->flag, 1u);
  EXPECT_EQ(reencode(*cw), "$CWOUT,1,0*5B");  // digest §10.2
}

}  // namespace
}  // namespace navfuse::frontends::unicore

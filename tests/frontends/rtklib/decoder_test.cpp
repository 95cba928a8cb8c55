// The RTKLIB solution reader on small files written here, against hand computation: GPST and
// UTC calendar times and week/seconds, degrees, dms and ECEF, Q as fix type, the signed
// square-rooted covariances as NED covariance, velocity, and damaged lines counted.
#include <gtest/gtest.h>

#include <cmath>

#include "frontends/rtklib/decoder.hpp"
#include "text_decode.hpp"

namespace navfuse::frontends::rtklib {
namespace {

using test::decode_text;

constexpr double kDeg = 3.14159265358979323846 / 180.0;
// 2025/08/28 is the Thursday of GPS week 2381 (Sunday 2025/08/24): 4 days + 17:30:39.749 =
// 345600 + 63039.749 = 408639.749 s of week, 2381 * 604800 = 1,440,028,800 s.
constexpr std::int64_t kT0Ns = (1'440'028'800LL + 408'639LL) * 1'000'000'000LL + 749'000'000LL;

TEST(RtklibPos, GpstDegreesWithCovariancesAndVelocity) {
  const std::string file =
      "% program   : RTKPOST demo5\n"
      "% (lat/lon/height=WGS84/ellipsoidal,Q=1:fix,2:float,3:sbas,4:dgps,5:single,6:ppp,ns=# of satellites)\n"
      "%  GPST            latitude(deg) longitude(deg) height(m) Q ns sdn(m) sde(m) sdu(m) sdne(m) sdeu(m) "
      "sdun(m) age(s) ratio vn(m/s) ve(m/s) vu(m/s) sdvn sdve sdvu sdvne sdveu sdvun\n"
      "2025/08/28 17:30:39.749 40.0966916 -105.1471665 1601.4350000 1 25 0.0100 0.0200 0.0300 0.0040 -0.0050 "
      "0.0060 0.0 0.0 0.1 0.2 0.3 0.05 0.06 0.07 0.0 0.0 0.0\n";
  PosDecoder decoder;
  const auto sink = decode_text(decoder, file);
  const auto pos = sink.all<GnssPosition>();
  const auto vel = sink.all<GnssVelocity>();
  ASSERT_EQ(pos.size(), 1u);
  ASSERT_EQ(vel.size(), 1u);
  const GnssPosition& p = pos[0];
  EXPECT_EQ(p.header.time_ns, kT0Ns);
  EXPECT_EQ(p.header.time_source, TimeSource::kGps);
  EXPECT_EQ(p.fix, GnssFixType::kRtkFixed);
  EXPECT_EQ(p.num_sats, 25);
  EXPECT_DOUBLE_EQ(p.lat_rad, 40.0966916 * kDeg);
  EXPECT_DOUBLE_EQ(p.lon_rad, -105.1471665 * kDeg);
  EXPECT_DOUBLE_EQ(p.height_m, 1601.435);
  EXPECT_NE(p.header.valid & GnssPosition::kValidCovariance, 0u);
  // var n, e, u = 0.01^2, 0.02^2, 0.03^2; cov ne = +0.004^2, eu = -(0.005^2), un = +0.006^2;
  // in NED the up rows/columns change sign: (n,d) = -un, (e,d) = -eu.
  const Eigen::Matrix3d& c = p.cov_ned_m2;
  EXPECT_NEAR(c(0, 0), 1.0e-4, 1e-15);
  EXPECT_NEAR(c(1, 1), 4.0e-4, 1e-15);
  EXPECT_NEAR(c(2, 2), 9.0e-4, 1e-15);
  EXPECT_NEAR(c(0, 1), 1.6e-5, 1e-15);
  EXPECT_NEAR(c(1, 2), 2.5e-5, 1e-15);
  EXPECT_NEAR(c(0, 2), -3.6e-5, 1e-15);
  EXPECT_EQ(c, c.transpose());
  const GnssVelocity& v = vel[0];
  EXPECT_EQ(v.header.time_ns, kT0Ns);
  EXPECT_NEAR((v.vel_ned_mps - Eigen::Vector3d(0.1, 0.2, -0.3)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(v.cov_ned_m2ps2(0, 0), 0.0025, 1e-15);
  EXPECT_NEAR(v.cov_ned_m2ps2(2, 2), 0.0049, 1e-15);
  EXPECT_EQ(v.fix, GnssFixType::kRtkFixed);
  EXPECT_EQ(decoder.counters().frames, 1u);
  EXPECT_EQ(decoder.counters().unknown_frames, 3u);
  EXPECT_EQ(decoder.counters().bad_frames, 0u);
}

TEST(RtklibPos, UtcAndDegreesMinutesSeconds) {
  // 17:30:21.749 UTC + 18 leap seconds (since 2017) = 17:30:39.749 GPST.
  // 40 05 48.08976 = 40 + 5/60 + 48.08976/3600 = 40.0966916 deg; -105 08 49.79940 = -105.1471665.
  const std::string file =
      "%  UTC                   latitude(d'\")   longitude(d'\")  height(m)   Q  ns   sdn(m)   sde(m)   sdu(m)  "
      "sdne(m)  sdeu(m)  sdun(m) age(s)  ratio\n"
      "2025/08/28 17:30:21.749   40 05 48.08976 -105 08 49.79940  1601.4350   2  12   0.1000   0.1000   0.2000   "
      "0.0000   0.0000   0.0000   1.00    0.0\n"
      "2025/08/28 17:30:22.749   -0 30 00.00000    0 00 36.00000     0.0000   5   7   1.0000   1.0000   1.0000   "
      "0.0000   0.0000   0.0000   0.00    0.0\n";
  PosDecoder decoder;
  const auto sink = decode_text(decoder, file);
  const auto pos = sink.all<GnssPosition>();
  ASSERT_EQ(pos.size(), 2u);
  EXPECT_TRUE(sink.all<GnssVelocity>().empty());
  EXPECT_EQ(pos[0].header.time_ns, kT0Ns);
  EXPECT_NEAR(pos[0].lat_rad / kDeg, 40.0966916, 5e-8);
  EXPECT_NEAR(pos[0].lon_rad / kDeg, -105.1471665, 5e-8);
  EXPECT_EQ(pos[0].fix, GnssFixType::kRtkFloat);
  EXPECT_NEAR(pos[0].cov_ned_m2(2, 2), 0.04, 1e-15);
  // "-0 30 00": the sign is on a zero degree field.
  EXPECT_NEAR(pos[1].lat_rad / kDeg, -0.5, 1e-12);
  EXPECT_NEAR(pos[1].lon_rad / kDeg, 0.01, 1e-12);
  EXPECT_EQ(pos[1].fix, GnssFixType::kFix3D);
  EXPECT_EQ(pos[1].header.time_ns, kT0Ns + 1'000'000'000LL);
}

TEST(RtklibPos, WeekSecondsAndEcefRotatedIntoNed) {
  // At latitude 0, longitude 0 the ECEF axes are x = up, y = east, z = north. sdx 1, sdy 2,
  // sdz 3 m: down 1, east 4, north 9 m^2; sdxy +0.5 -> cov(x,y) = 0.25 -> cov(d,e) = -0.25.
  const std::string file =
      "%  GPST                  x-ecef(m)      y-ecef(m)      z-ecef(m)   Q  ns   sdx(m)   sdy(m)   sdz(m)  "
      "sdxy(m)  sdyz(m)  sdzx(m) age(s)  ratio\n"
      "2381 408639.749   6378137.0000  0.0000  0.0000   4  9   1.0000   2.0000   3.0000   0.5000   0.0000   "
      "0.0000   0.00    0.0\n";
  PosDecoder decoder;
  const auto pos = decode_text(decoder, file).all<GnssPosition>();
  ASSERT_EQ(pos.size(), 1u);
  EXPECT_EQ(pos[0].header.time_ns, kT0Ns);
  EXPECT_NEAR(pos[0].lat_rad, 0.0, 1e-12);
  EXPECT_NEAR(pos[0].lon_rad, 0.0, 1e-12);
  EXPECT_NEAR(pos[0].height_m, 0.0, 1e-6);
  EXPECT_EQ(pos[0].fix, GnssFixType::kDgnss);
  const Eigen::Matrix3d& c = pos[0].cov_ned_m2;
  EXPECT_NEAR(c(0, 0), 9.0, 1e-9);
  EXPECT_NEAR(c(1, 1), 4.0, 1e-9);
  EXPECT_NEAR(c(2, 2), 1.0, 1e-9);
  EXPECT_NEAR(c(1, 2), -0.25, 1e-9);
  EXPECT_NEAR(c(0, 1), 0.0, 1e-9);
}

TEST(RtklibPos, WithoutAHeaderTheDefaultLayoutIsRead) {
  const std::string file = "2381 408639.749 40.0 -105.0 1600.0 6 20 0.05 0.05 0.1 0 0 0 0 0\n";
  PosDecoder decoder;
  const auto pos = decode_text(decoder, file).all<GnssPosition>();
  ASSERT_EQ(pos.size(), 1u);
  EXPECT_EQ(pos[0].fix, GnssFixType::kPpp);
  EXPECT_NEAR(pos[0].cov_ned_m2(0, 0), 0.0025, 1e-15);
}

TEST(RtklibPos, DamagedLinesAreCountedAndSkipped) {
  const std::string good = "2025/08/28 17:30:39.749 40.0 -105.0 1600.0 1 25 0.01 0.01 0.01 0 0 0 0 0\n";
  const std::string file =
      "%  GPST  latitude(deg) longitude(deg) height(m) Q ns sdn(m) sde(m) sdu(m) sdne(m) sdeu(m) sdun(m) age(s) ratio\n" +
      good +
      "2025/08/28 17:30:40.000 40.0 -105.0\n"                                           // too few fields
      "2025/13/28 17:30:40.249 40.0 -105.0 1600.0 1 25 0.01 0.01 0.01 0 0 0 0 0\n"      // month 13
      "2025/08/28 17:30:40.499 40.0 -105.0 1600.0 9 25 0.01 0.01 0.01 0 0 0 0 0\n"      // Q 9
      "2025/08/28 17:30:40.749 40.0 -105.0 1600.0 1 25 nan 0.01 0.01 0 0 0 0 0\n"       // NaN
      "2025/08/28 17:30:40.999 40.0 -105.0 1600.0 1 25 -0.01 0.01 0.01 0 0 0 0 0\n"     // negative std
      "2025/08/28 17:30:41.249 95.0 -105.0 1600.0 1 25 0.01 0.01 0.01 0 0 0 0 0\n" +    // latitude > 90
      good;
  PosDecoder decoder;
  const auto sink = decode_text(decoder, file);
  EXPECT_EQ(sink.all<GnssPosition>().size(), 2u);
  EXPECT_EQ(decoder.counters().frames, 2u);
  EXPECT_EQ(decoder.counters().bad_frames, 6u);
  EXPECT_EQ(decoder.counters().unknown_frames, 1u);
}

TEST(RtklibPos, ZeroStdDevsLeaveTheCovarianceInvalid) {
  PosDecoder decoder;
  const auto pos =
      decode_text(decoder, "2381 408639.749 40.0 -105.0 1600.0 5 8 0 0 0 0 0 0 0 0\n").all<GnssPosition>();
  ASSERT_EQ(pos.size(), 1u);
  EXPECT_EQ(pos[0].header.valid & GnssPosition::kValidCovariance, 0u);
}

}  // namespace
}  // namespace navfuse::frontends::rtklib

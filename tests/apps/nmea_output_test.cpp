// navfuse's NMEA output (apps/output/nmea_epoch_encoder.hpp) against sentences written out by
// hand: fields from the NMEA 0183 GGA / RMC / HDT layouts, checksums the XOR of the characters
// between '$' and '*' worked out independently of the encoder.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "apps/output/nmea_epoch_encoder.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

// GPS week 2300, TOW 302400 s is 2024-02-07 12:00:00 GPS, 11:59:42 UTC (18 leap seconds).
constexpr std::int64_t kGpsNs = (2300LL * 604'800LL + 302'400LL) * 1'000'000'000LL;

NavSolution navigating() {
  NavSolution s;
  s.header.time_ns = kGpsNs;
  s.header.time_source = TimeSource::kGps;
  s.header.valid = NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
                   NavSolution::kValidHeading | NavSolution::kValidUndulation;
  s.mode = NavMode::kNavigation;
  s.gnss_fix = GnssFixType::kFix3D;
  s.lat_rad = 48.1173 * rot::kDegToRad;  // 48 deg 07.038 min N
  s.lon_rad = 11.5 * rot::kDegToRad;     // 11 deg 30 min E
  s.height_m = 545.4;
  s.undulation_m = 46.9;                 // MSL altitude 498.5 m
  s.vel_ned_mps = {-5.0, 5.0, 0.0};      // 7.0711 m/s = 13.745 kn towards 135 deg
  s.rpy_rad = {0.0, 0.0, 92.5 * rot::kDegToRad};
  return s;
}

std::string sentences(const NavSolution& s, std::uint8_t num_sats) {
  std::vector<std::uint8_t> out;
  append_nmea_sentences(s, num_sats, out);
  return {out.begin(), out.end()};
}

TEST(NmeaOutput, NavigatingSolutionAsGgaRmcHdt) {
  EXPECT_EQ(sentences(navigating(), 8),
            "$GNGGA,115942.00,4807.038000,N,01130.000000,E,1,08,,498.500,M,46.900,M,,*56\r\n"
            "$GNRMC,115942.00,A,4807.038000,N,01130.000000,E,13.745,135.00,070224,,,A*49\r\n"
            "$GNHDT,92.50,T*25\r\n");
}

TEST(NmeaOutput, NoPositionIsQualityZeroAndStatusV) {
  NavSolution s = navigating();
  s.header.valid = NavSolution::kValidAttitude;  // levelled only: no position, velocity, heading
  s.mode = NavMode::kVerticalGyro;
  EXPECT_EQ(sentences(s, 8),
            "$GNGGA,115942.00,,,,,0,,,,,,M,,*11\r\n"
            "$GNRMC,115942.00,V,,,,,,,070224,,,N*6A\r\n");
}

TEST(NmeaOutput, AtMostTenHzAtPoseEpochs) {
  NmeaEpochEncoder encoder;
  std::vector<std::uint8_t> out;
  int written = 0;
  for (int i = 0; i < 200; ++i) {  // 2 s of 100 Hz poses, every other one due
    OutputEpoch e;
    e.solution = navigating();
    e.solution.header.time_ns = kGpsNs + i * 10'000'000LL;
    e.pose_due = i % 2 == 0;
    const std::size_t before = out.size();
    encoder.append(e, out);
    if (out.size() != before) ++written;
  }
  EXPECT_EQ(written, 20);
}

}  // namespace
}  // namespace navfuse::apps

// The rover position `navfuse run --corrections ...?gga=S` reports to a network-RTK caster
// (apps/run/rover_position.hpp): the GGA sentence of the latest solution with a position,
// written out by hand from the NMEA 0183 GGA layout (checksum worked out apart from navfuse).
#include "apps/run/rover_position.hpp"

#include <gtest/gtest.h>

#include <string>
#include <thread>

#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

// GPS week 2300, TOW 302400 s is 2024-02-07 12:00:00 GPS, 11:59:42 UTC (18 leap seconds).
constexpr std::int64_t kGpsNs = (2300LL * 604'800LL + 302'400LL) * 1'000'000'000LL;
// 52.5163 N = 52 deg 30.978 min, 13.3777 E = 13 deg 22.662 min; MSL 80.0 - 39.5 = 40.5 m.
// Checksum: XOR of "GNGGA,...,M,," = 0x6C.
constexpr const char* kGga = "$GNGGA,115942.00,5230.978000,N,01322.662000,E,4,12,,40.500,M,39.500,M,,*6C\r\n";

OutputEpoch rtk_fixed_epoch() {
  OutputEpoch e;
  NavSolution& s = e.solution;
  s.header.time_ns = kGpsNs;
  s.header.time_source = TimeSource::kGps;
  s.header.valid = NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidUndulation;
  s.mode = NavMode::kNavigation;
  s.gnss_fix = GnssFixType::kRtkFixed;
  s.lat_rad = 52.5163 * rot::kDegToRad;
  s.lon_rad = 13.3777 * rot::kDegToRad;
  s.height_m = 80.0;
  s.undulation_m = 39.5;
  e.num_sats = 12;
  e.pose_due = true;
  return e;
}

std::string gga_of(const RoverPosition& p) {
  std::vector<std::uint8_t> out;
  if (!p.append_gga(out)) return "(none)";
  return {out.begin(), out.end()};
}

TEST(RoverPosition, NothingBeforeThePositionIsKnown) {
  RoverPosition p;
  EXPECT_EQ(gga_of(p), "(none)");
  OutputEpoch levelled = rtk_fixed_epoch();
  levelled.solution.header.valid = NavSolution::kValidAttitude;  // aligning: no position yet
  p.update(levelled);
  EXPECT_EQ(gga_of(p), "(none)");
}

TEST(RoverPosition, TheLatestPositionAsGga) {
  RoverPosition p;
  p.update(rtk_fixed_epoch());
  EXPECT_EQ(gga_of(p), kGga);
}

TEST(RoverPosition, KeepsTheLastPositionWhenTheFilterLosesIt) {
  RoverPosition p;
  p.update(rtk_fixed_epoch());
  OutputEpoch lost = rtk_fixed_epoch();
  lost.solution.header.valid = 0;  // a filter restart
  lost.solution.lat_rad = 0.0;
  p.update(lost);
  EXPECT_EQ(gga_of(p), kGga);
  OutputEpoch between = rtk_fixed_epoch();
  between.pose_due = false;  // not a pose epoch: not taken
  between.solution.lat_rad = 10.0 * rot::kDegToRad;
  p.update(between);
  EXPECT_EQ(gga_of(p), kGga);
}

TEST(RoverPosition, ReadWhileTheFilterThreadWrites) {
  RoverPosition p;
  OutputEpoch a = rtk_fixed_epoch();
  OutputEpoch b = rtk_fixed_epoch();
  b.solution.lat_rad = -33.5 * rot::kDegToRad;
  std::thread writer([&] {
    for (int i = 0; i < 20000; ++i) p.update(i % 2 == 0 ? a : b);
  });
  // Every sentence read is one of the two whole positions, never a mix (the mutex).
  int seen = 0;
  while (seen < 2000) {
    const std::string s = gga_of(p);
    if (s == "(none)") continue;
    ++seen;
    ASSERT_TRUE(s == kGga || s.find(",3330.000000,S,01322.662000,E,4,12,") != std::string::npos) << s;
  }
  writer.join();
}

}  // namespace
}  // namespace navfuse::apps

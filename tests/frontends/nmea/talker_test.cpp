// Satellite numbering of the two dialects (Unicore spec L935, L964, L1157, L1184).
#include <gtest/gtest.h>

#include "frontends/nmea/talker.hpp"

namespace navfuse::frontends::nmea {
namespace {

TEST(NmeaTalker, H30GlobalNumbering) {
  // h30: BDS 161~197 (160 + PRN), Galileo 101~136 (L1157); the $BDGSV example lists 161, 163 ...
  EXPECT_EQ(sat_from_nmea(161, {'B', 'D'}, Dialect::kH30).system, SatSystem::kBeidou);
  EXPECT_EQ(sat_from_nmea(161, {'B', 'D'}, Dialect::kH30).prn, 1);
  EXPECT_EQ(sat_from_nmea(136, {'G', 'N'}, Dialect::kH30).system, SatSystem::kGalileo);
  EXPECT_EQ(sat_from_nmea(136, {'G', 'N'}, Dialect::kH30).prn, 36);
  EXPECT_EQ(sat_from_nmea(3, {'G', 'P'}, Dialect::kH30).system, SatSystem::kGps);
}

TEST(NmeaTalker, H51PerTalkerNumbering) {
  // h51: BDS 01~37 under GB, overlapping the SBAS range 33-64 (L935).
  EXPECT_EQ(sat_from_nmea(37, {'G', 'B'}, Dialect::kH51).system, SatSystem::kBeidou);
  EXPECT_EQ(sat_from_nmea(37, {'G', 'P'}, Dialect::kH51).system, SatSystem::kSbas);
  EXPECT_EQ(sat_from_nmea(33, {'G', 'P'}, Dialect::kH51).prn, 120);  // first SBAS PRN
  EXPECT_EQ(sat_from_nmea(65, {'G', 'L'}, Dialect::kH51).system, SatSystem::kGlonass);
  EXPECT_EQ(sat_from_nmea(65, {'G', 'L'}, Dialect::kH51).prn, 1);
  EXPECT_EQ(sat_from_nmea(193, {'G', 'P'}, Dialect::kH51).system, SatSystem::kQzss);
}

TEST(NmeaTalker, NumberingRoundTrips) {
  for (Dialect d : {Dialect::kH51, Dialect::kH30}) {
    for (const SatId id : {SatId{SatSystem::kBeidou, 14}, SatId{SatSystem::kGalileo, 30},
                           SatId{SatSystem::kGlonass, 24}, SatId{SatSystem::kSbas, 133}}) {
      const Talker t = id.system == SatSystem::kBeidou ? Talker{'G', 'B'}
                       : id.system == SatSystem::kGalileo ? Talker{'G', 'A'}
                                                            : Talker{'G', 'P'};
      const SatId back = sat_from_nmea(nmea_from_sat(id, d), t, d);
      EXPECT_EQ(back.system, id.system);
      EXPECT_EQ(back.prn, id.prn);
    }
  }
}

}  // namespace
}  // namespace navfuse::frontends::nmea

// The real walk in ../shared/captures/real/walk_0827 (README there): gnss.pos, RTKLIB's solution
// unchanged, reads line for line (one header, 536 epochs: 349 fixed, 187 float, each with
// velocity); the format is detected as rtklib and the IMU text as imutxt. Skips when absent.
#include <gtest/gtest.h>

#include "frontends/imutxt/frontend.hpp"
#include "frontends/rtklib/decoder.hpp"
#include "frontends/rtklib/frontend.hpp"
#include "text_decode.hpp"

namespace navfuse::frontends::rtklib {
namespace {

TEST(RtklibCapture, EveryEpochOfTheWalkReads) {
  const auto text = test::read_shared("captures/real/walk_0827/gnss.pos");
  if (!text) GTEST_SKIP() << "capture not present";
  PosDecoder decoder;
  const auto sink = test::decode_text(decoder, *text, 4096);
  EXPECT_EQ(test::count_lines(*text), 537u);
  EXPECT_EQ(decoder.counters().frames, 536u);
  EXPECT_EQ(decoder.counters().unknown_frames, 1u);
  EXPECT_EQ(decoder.counters().bad_frames, 0u);
  const auto pos = sink.all<GnssPosition>();
  ASSERT_EQ(pos.size(), 536u);
  EXPECT_EQ(sink.all<GnssVelocity>().size(), 536u);
  std::size_t fixed = 0, floats = 0;
  for (const auto& p : pos) {
    fixed += p.fix == GnssFixType::kRtkFixed ? 1 : 0;
    floats += p.fix == GnssFixType::kRtkFloat ? 1 : 0;
  }
  EXPECT_EQ(fixed, 349u);
  EXPECT_EQ(floats, 187u);
  // First epoch: 2025/08/28 17:30:39.749 GPST = week 2381, 408639.749 s; sdn 0.0098995 m.
  EXPECT_EQ(pos.front().header.time_ns, time::gps_ns_from_week_tow(2381, 408639.749));
  EXPECT_NEAR(pos.front().cov_ned_m2(0, 0), 0.0098995 * 0.0098995, 1e-12);
}

TEST(RtklibCapture, DetectionPicksEachReaderForItsFile) {
  const auto pos = test::read_shared("captures/real/walk_0827/gnss.pos");
  const auto imu = test::read_shared("captures/real/walk_0827/imu.txt");
  if (!pos || !imu) GTEST_SKIP() << "capture not present";
  const auto head = [](const std::string& s) { return test::bytes_of(std::string_view(s).substr(0, 64 * 1024)); };
  EXPECT_GT(rtklib::frontend().probe(head(*pos)), 0u);
  EXPECT_EQ(imutxt::frontend().probe(head(*pos)), 0u);
  EXPECT_GT(imutxt::frontend().probe(head(*imu)), 0u);
  EXPECT_EQ(rtklib::frontend().probe(head(*imu)), 0u);
}

}  // namespace
}  // namespace navfuse::frontends::rtklib

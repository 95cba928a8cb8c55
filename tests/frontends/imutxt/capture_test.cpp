// The real walk in ../shared/captures/real/walk_0827 (README there): every line of imu.txt reads
// as a sample, in GPS week 2381. Skips when the shared folder is absent.
#include <gtest/gtest.h>

#include "frontends/imutxt/decoder.hpp"
#include "text_decode.hpp"

namespace navfuse::frontends::imutxt {
namespace {

TEST(ImuTextCapture, EveryLineOfTheWalkIsASample) {
  const auto text = test::read_shared("captures/real/walk_0827/imu.txt");
  if (!text) GTEST_SKIP() << "capture not present";
  ImuTextDecoder decoder(2381);
  const auto sink = test::decode_text(decoder, *text, 64 * 1024);
  const std::size_t lines = test::count_lines(*text);
  EXPECT_EQ(lines, 20454u);  // README: 20,454 lines
  EXPECT_EQ(decoder.counters().frames, lines);
  EXPECT_EQ(decoder.counters().bad_frames, 0u);
  EXPECT_EQ(decoder.counters().unknown_frames, 0u);
  const auto imu = sink.all<ImuSample>();
  ASSERT_EQ(imu.size(), lines);
  // First line: 408640.967001 s of week 2381; ~167 Hz: dt 6 to 9 ms throughout.
  EXPECT_EQ(imu.front().header.time_ns, time::gps_ns_from_week_tow(2381, 408640.967001));
  for (std::size_t i = 1; i < imu.size(); ++i) {
    ASSERT_GT(imu[i].dt_s, 0.004) << i;
    ASSERT_LT(imu[i].dt_s, 0.0095) << i;
  }
}

}  // namespace
}  // namespace navfuse::frontends::imutxt

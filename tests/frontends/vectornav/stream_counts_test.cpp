// A whole VN-300 log through the StreamDecoder: counters and measurement counts by kind equal
// what the encoder put in, also with noise between frames and corrupted frames.
#include <gtest/gtest.h>

#include <random>

#include "frontends/vectornav/frontend.hpp"
#include "stream_fixture.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::vectornav {
namespace {

TEST(VnStreamCounts, CleanLogMatchesWhatWasWritten) {
  const test::StreamContent c = test::make_vn_stream(2000);  // 10 s
  ASSERT_EQ(c.count(MeasurementKind::kImu), 2000u);
  ASSERT_EQ(c.count(MeasurementKind::kGnssPosition), 100u);
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, c.bytes, sink);
  const StreamCounters& k = d.counters();
  EXPECT_EQ(k.bytes, c.bytes.size());
  EXPECT_EQ(k.frames, c.frames);
  EXPECT_EQ(k.bad_frames, 0u);
  EXPECT_EQ(k.skipped_bytes, 0u);
  EXPECT_EQ(k.unknown_frames, 0u);
  EXPECT_EQ(k.decode_errors, 0u);
  EXPECT_EQ(sink.by_kind, c.by_kind);
  for (const auto& m : sink.measurements) EXPECT_EQ(header_of(m).time_source, TimeSource::kGps);
}

TEST(VnStreamCounts, NoiseBetweenFramesIsSkippedAndCounted) {
  // Noise made of bytes that can never start a frame (no 0xFA, 0xFB or '$'), so the skipped
  // count is exactly the noise length.
  const test::StreamContent c = test::make_vn_stream(400);
  std::mt19937_64 rng(5);
  std::vector<std::uint8_t> noisy;
  std::size_t noise = 0;
  std::vector<std::pair<std::size_t, std::size_t>> frames;  // (offset, length)
  // Insert noise at random byte positions between frames: re-frame the clean log to find them.
  PortFramer framer;
  framer.feed(c.bytes, [&](const Frame& f) { frames.emplace_back(f.offset, f.bytes.size()); });
  for (const auto& [off, len] : frames) {
    const std::size_t n = rng() % 20;
    for (std::size_t i = 0; i < n; ++i) {
      std::uint8_t b;
      do b = static_cast<std::uint8_t>(rng()); while (b == 0xFA || b == 0xFB || b == '$');
      noisy.push_back(b);
    }
    noise += n;
    noisy.insert(noisy.end(), c.bytes.begin() + static_cast<std::ptrdiff_t>(off),
                 c.bytes.begin() + static_cast<std::ptrdiff_t>(off + len));
  }
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, noisy, sink);
  EXPECT_EQ(d.counters().frames, c.frames);
  EXPECT_EQ(d.counters().skipped_bytes, noise);
  EXPECT_EQ(d.counters().bad_frames, 0u);
  EXPECT_EQ(sink.by_kind, c.by_kind);
}

TEST(VnStreamCounts, CorruptedFramesAreLostAloneAndNeighboursSurvive) {
  const test::StreamContent c = test::make_vn_stream(400);
  std::vector<std::pair<std::size_t, std::size_t>> frames;
  PortFramer framer;
  framer.feed(c.bytes, [&](const Frame& f) { frames.emplace_back(f.offset, f.bytes.size()); });
  ASSERT_EQ(frames.size(), c.frames);
  // Flip one payload bit in every 10th frame (never the sync byte).
  std::vector<std::uint8_t> bytes = c.bytes;
  std::size_t corrupted = 0;
  for (std::size_t k = 0; k < frames.size(); k += 10) {
    bytes[frames[k].first + frames[k].second - 3] ^= 0x10;
    ++corrupted;
  }
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, bytes, sink);
  EXPECT_EQ(d.counters().frames, c.frames - corrupted);
  EXPECT_GE(d.counters().bad_frames, corrupted);
  EXPECT_EQ(d.counters().bytes, d.framed_bytes() + d.counters().skipped_bytes);
}

TEST(VnStreamCounts, ProbeRecognisesTheLogAndNotOtherText) {
  const test::StreamContent c = test::make_vn_stream(200);
  const std::span<const std::uint8_t> head(c.bytes.data(), std::min<std::size_t>(c.bytes.size(), 65536));
  EXPECT_GT(frontend().probe(head), 100u);
  const auto nmea = test::text_bytes("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n");
  EXPECT_EQ(frontend().probe(nmea), 0u);
  EXPECT_EQ(frontend().format, "vn");
  EXPECT_EQ(frontend().make_decoder()->format(), "vn");
}

}  // namespace
}  // namespace navfuse::frontends::vectornav

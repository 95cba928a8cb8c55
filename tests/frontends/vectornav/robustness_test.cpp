// Bad input never crashes the decoder or reads out of bounds, is counted, and chunking does not
// change the result: truncation at every length, every single-bit flip, absurd lengths,
// garbage, random split points.
#include <gtest/gtest.h>

#include <random>

#include "frontends/vectornav/ascii_sentence.hpp"
#include "frontends/vectornav/binary_codec.hpp"
#include "stream_fixture.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::vectornav {
namespace {

void expect_accounting(const VnStreamDecoder& d) {
  const StreamCounters& k = d.counters();
  EXPECT_EQ(k.bytes, d.framed_bytes() + k.skipped_bytes + d.buffered_bytes());
  EXPECT_LE(k.unknown_frames + k.decode_errors, k.frames + k.decode_errors);
}

// Offsets and lengths of the frames of a clean stream.
std::vector<std::pair<std::size_t, std::size_t>> frame_spans(const std::vector<std::uint8_t>& bytes) {
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  PortFramer f;
  f.feed(bytes, [&](const Frame& fr) { spans.emplace_back(fr.offset, fr.bytes.size()); });
  return spans;
}

TEST(VnRobustness, TruncationAtEveryLength) {
  const test::StreamContent c = test::make_vn_stream(41);  // IMU, INS, GNSS, heading, speed frames
  const auto spans = frame_spans(c.bytes);
  const std::size_t total = std::min<std::size_t>(c.bytes.size(), 1500);
  for (std::size_t len = 0; len <= total; ++len) {
    std::vector<std::uint8_t> prefix(c.bytes.begin(), c.bytes.begin() + static_cast<std::ptrdiff_t>(len));
    VnStreamDecoder d;
    test::CollectingSink sink;
    d.feed(prefix, sink);
    expect_accounting(d);
    d.finish(sink);
    std::size_t complete = 0;
    for (const auto& [off, n] : spans) complete += off + n <= len;
    ASSERT_EQ(d.counters().frames, complete) << len;
    ASSERT_EQ(d.buffered_bytes(), 0u);
    expect_accounting(d);
  }
}

TEST(VnRobustness, EverySingleBitFlipIsRejected) {
  const test::StreamContent c = test::make_vn_stream(1);
  const auto spans = frame_spans(c.bytes);
  for (const auto& [off, n] : spans) {
    for (std::size_t bit = 0; bit < n * 8; ++bit) {
      std::vector<std::uint8_t> frame(c.bytes.begin() + static_cast<std::ptrdiff_t>(off),
                                      c.bytes.begin() + static_cast<std::ptrdiff_t>(off + n));
      frame[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
      VnStreamDecoder d;
      test::CollectingSink sink;
      test::decode_all(d, frame, sink);
      // CRC16 and the ASCII checksums detect every single-bit error; a flip in the CR/LF
      // turns the line into a non-terminated one.
      ASSERT_EQ(d.counters().frames, 0u) << "frame at " << off << " bit " << bit;
      ASSERT_TRUE(sink.measurements.empty());
      expect_accounting(d);
    }
  }
}

TEST(VnRobustness, AbsurdLengthsAreNotFramesAndDoNotStall) {
  const test::StreamContent c = test::make_vn_stream(1);
  std::vector<std::vector<std::uint8_t>> bad = {
      // Split packet claiming 65535 payload bytes.
      test::from_hex("FB 00 01 21 FF FF 00 00"),
      // GNSS1 SatInfo with Count 255: 2 + 8*255 bytes > 600.
      test::from_hex("FA 08 00 40 FF 00"),
      // RawMeas with 255 signals (second type word bit 0, needs the extension bit).
      test::from_hex("FA 08 00 80 01 00 00 00 00 00 00 00 00 00 00 00 FF 00"),
      // Five group bytes with extension bits.
      test::from_hex("FA 81 80 80 80 01 01 00"),
      // Unknown type bit (Attitude bit 0) and unknown group (bit 8).
      test::from_hex("FA 10 01 00 00 00"), test::from_hex("FA 80 01 01 00"),
      // Three type words in one group.
      test::from_hex("FA 01 00 80 00 80 01 00"),
  };
  // An endless ASCII line.
  bad.push_back(std::vector<std::uint8_t>(2000, 'A'));
  bad.back()[0] = '$';
  for (const auto& b : bad) {
    std::vector<std::uint8_t> stream = b;
    stream.insert(stream.end(), c.bytes.begin(), c.bytes.end());
    VnStreamDecoder d;
    test::CollectingSink sink;
    d.feed(stream, sink);
    // The real frames after the bad header are found without waiting for more bytes.
    EXPECT_EQ(d.counters().frames, c.frames);
    EXPECT_EQ(d.counters().skipped_bytes, b.size());
    expect_accounting(d);
  }
}

TEST(VnRobustness, GarbageNeverCrashesAndIsAccounted) {
  std::mt19937_64 rng(99);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint8_t> g(1 + rng() % 3000);
    for (auto& b : g) {
      // Bias towards sync bytes and header-like values so candidates get deep.
      const auto r = rng() % 8;
      b = r == 0 ? 0xFA : r == 1 ? 0xFB : r == 2 ? '$' : static_cast<std::uint8_t>(rng());
    }
    VnStreamDecoder d;
    test::CollectingSink sink;
    d.feed(g, sink);
    expect_accounting(d);
    d.finish(sink);
    expect_accounting(d);
    EXPECT_EQ(d.buffered_bytes(), 0u);
  }
}

TEST(VnRobustness, ChunkedFeedingEqualsOneFeed) {
  // A stream with noise and corruption, fed whole and at random split points.
  const test::StreamContent c = test::make_vn_stream(400);
  std::mt19937_64 rng(3);
  std::vector<std::uint8_t> bytes = c.bytes;
  for (std::size_t i = 0; i < bytes.size(); ++i)
    if (rng() % 100 == 0) bytes[i] = static_cast<std::uint8_t>(rng());
  VnStreamDecoder whole;
  test::CollectingSink whole_sink(true);
  test::decode_all(whole, bytes, whole_sink);
  for (int trial = 0; trial < 20; ++trial) {
    VnStreamDecoder d;
    test::CollectingSink sink(true);
    std::size_t at = 0;
    while (at < bytes.size()) {
      const std::size_t n = std::min<std::size_t>(bytes.size() - at, trial == 0 ? 1 : 1 + rng() % 700);
      d.feed(std::span(bytes).subspan(at, n), sink);
      at += n;
    }
    d.finish(sink);
    const StreamCounters& a = whole.counters();
    const StreamCounters& b = d.counters();
    EXPECT_EQ(a.bytes, b.bytes);
    EXPECT_EQ(a.frames, b.frames);
    EXPECT_EQ(a.bad_frames, b.bad_frames);
    EXPECT_EQ(a.skipped_bytes, b.skipped_bytes);
    EXPECT_EQ(a.decode_errors, b.decode_errors);
    EXPECT_EQ(a.unknown_frames, b.unknown_frames);
    EXPECT_EQ(sink.by_kind, whole_sink.by_kind);
    ASSERT_EQ(sink.records.size(), whole_sink.records.size());
    for (std::size_t i = 0; i < sink.records.size(); ++i) {
      EXPECT_EQ(sink.records[i].offset, whole_sink.records[i].offset);
      EXPECT_EQ(sink.records[i].fields, whole_sink.records[i].fields);
    }
  }
}

TEST(VnRobustness, NonFiniteAndOutOfRangeFieldsAreSafe) {
  // NaN DeltaTime, NaN quaternion, undefined GnssFix 5, times beyond int64: no UB, counted.
  BinaryMessage m;
  m.header.set(kSlotTime, time_type::kTimeGps);
  m.header.set(kSlotTime, time_type::kTimeStartup);
  m.header.set(kSlotImu, imu_type::kDeltaTheta);
  m.header.set(kSlotAttitude, attitude_type::kQuaternion);
  m.header.set(kSlotGnss1, gnss_type::kGnssFix);
  m.header.set(kSlotGnss1, gnss_type::kPosLla);
  m.time.time_gps_ns = ~std::uint64_t{0};
  m.time.time_startup_ns = ~std::uint64_t{0};
  m.imu.delta_time_s = std::numeric_limits<float>::quiet_NaN();
  m.attitude.quaternion.fill(std::numeric_limits<float>::quiet_NaN());
  m.gnss[0].fix = 5;
  std::vector<std::uint8_t> wire;
  ASSERT_TRUE(append_binary_message(m, wire));
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, wire, sink);
  EXPECT_EQ(d.counters().frames, 1u);
  EXPECT_EQ(d.counters().decode_errors, 1u);
  EXPECT_EQ(d.issues(DecodeIssue::kBinaryContent), 1u);
  EXPECT_EQ(sink.count(MeasurementKind::kImu), 0u);  // no interval: not a usable increment
  ASSERT_EQ(sink.count(MeasurementKind::kGnssPosition), 1u);
}

TEST(VnRobustness, NonNumericAsciiFieldsAreDecodeErrors) {
  // Checksums are valid; the content is not: NaN/inf enums, huge weeks, too few fields, text.
  const char* const bodies[] = {
      "VNGPS,501342.999609,2303,nan,16,+32.89195850,-096.70376580,+00163.653,-000.005,+000.005,+000.108,+001.433,"
      "+001.439,+003.605,+000.173,3.00E-09",
      "VNGPS,501342.999609,2303,4,inf,+32.89195850,-096.70376580,+00163.653,-000.005,+000.005,+000.108,+001.433,"
      "+001.439,+003.605,+000.173,3.00E-09",
      "VNINS,501384.439541,2303,XYZ,-177.963,+000.511,+004.425,+32.89195732,-096.70376518,+00164.947,-000.014,"
      "-000.005,-000.094,01.43,00.56,0.090",
      "VNYPR,+010.071,+000.278",
      "VNYPR,abc,+000.278,-002.026",
      "VNRRG,999,1",
      "VNERR,ZZ",
  };
  for (const char* b : bodies) {
    VnStreamDecoder d;
    test::CollectingSink sink;
    test::decode_all(d, test::text_bytes(make_sentence(b)), sink);
    EXPECT_EQ(d.counters().frames, 1u) << b;
    EXPECT_EQ(d.counters().decode_errors, 1u) << b;
    EXPECT_EQ(d.issues(DecodeIssue::kAsciiFields), 1u) << b;
    EXPECT_TRUE(sink.measurements.empty()) << b;
  }
  // A GPS week beyond any plausible date is ignored, not overflowed: the sentence keeps the
  // stream's latest (here: no) time.
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d,
                   test::text_bytes(make_sentence(
                       "VNGPS,501342.999609,60000,4,16,+32.89195850,-096.70376580,+00163.653,-000.005,+000.005,"
                       "+000.108,+001.433,+001.439,+003.605,+000.173,3.00E-09")),
                   sink);
  ASSERT_EQ(sink.count(MeasurementKind::kGnssPosition), 1u);
  EXPECT_EQ(header_of(sink.measurements[0]).time_source, TimeSource::kUnknown);
}

}  // namespace
}  // namespace navfuse::frontends::vectornav

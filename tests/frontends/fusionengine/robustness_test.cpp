// Bad input is counted and survived: garbage between frames, truncation at every length,
// every single-bit flip, absurd payload sizes, and chunked feeding at random split points
// giving exactly the result of one feed. Also: a stream written through the encoder comes back
// with counters and measurement counts equal to what was put in.
#include <gtest/gtest.h>

#include <random>

#include "core/rotation/rotation.hpp"
#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/encoder.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

constexpr std::int64_t kT0 = 1'400'000'000'000'000'000;

struct Stream {
  std::vector<std::uint8_t> bytes;
  std::vector<std::size_t> frame_sizes;
};

// Pose+PoseAux+GNSSInfo, IMU and heading messages from the encoder.
Stream sample_stream(int epochs) {
  FusionEngineEncoder encoder;
  Stream s;
  for (int i = 0; i < epochs; ++i) {
    const std::size_t before = s.bytes.size();
    ImuSample imu;
    imu.header = {kT0 + std::int64_t{i} * 10'000'000, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
    imu.frame = SensorFrame::kVehicle;
    imu.accel = {0.1 * i, 0.2, -9.8};
    encoder.encode(imu, s.bytes);
    s.frame_sizes.push_back(s.bytes.size() - before);
    if (i % 4 == 0) {
      NavSolution sol;
      sol.header = {kT0 + std::int64_t{i} * 10'000'000, TimeSource::kGps, 0,
                    NavSolution::kValidPosition | NavSolution::kValidAttitude | NavSolution::kValidVelocity};
      sol.mode = NavMode::kNavigation;
      sol.gnss_fix = GnssFixType::kFix3D;
      sol.lat_rad = 0.6;
      sol.lon_rad = 0.1 + 1e-7 * i;
      const std::size_t b = s.bytes.size();
      encoder.encode(sol, s.bytes);  // 3 frames
      (void)b;
      s.frame_sizes.push_back(kHeaderSize + PoseMessage::kSize);
      s.frame_sizes.push_back(kHeaderSize + PoseAuxMessage::kSize);
      s.frame_sizes.push_back(kHeaderSize + GnssInfoMessage::kSize);
    }
  }
  return s;
}

struct Result {
  frontends::StreamCounters counters;
  std::vector<Measurement> measurements;
};
Result decode_chunks(std::span<const std::uint8_t> bytes, const std::vector<std::size_t>& cuts) {
  FusionEngineDecoder d;
  test::CollectingSink sink;
  std::size_t at = 0;
  for (std::size_t cut : cuts) {
    d.feed(bytes.subspan(at, cut - at), sink);
    at = cut;
  }
  d.feed(bytes.subspan(at), sink);
  d.finish(sink);
  return {d.counters(), sink.measurements};
}
Result decode_all(std::span<const std::uint8_t> bytes) { return decode_chunks(bytes, {}); }

bool same_counters(const frontends::StreamCounters& a, const frontends::StreamCounters& b) {
  return a.bytes == b.bytes && a.frames == b.frames && a.bad_frames == b.bad_frames &&
         a.skipped_bytes == b.skipped_bytes && a.unknown_frames == b.unknown_frames &&
         a.decode_errors == b.decode_errors;
}

TEST(FeRobustness, GarbageBetweenFramesIsSkippedAndCounted) {
  const Stream s = sample_stream(12);
  std::mt19937_64 rng(11);
  std::vector<std::uint8_t> mixed;
  std::size_t garbage = 0;
  std::size_t at = 0;
  for (std::size_t size : s.frame_sizes) {
    const std::size_t n = rng() % 40;
    for (std::size_t k = 0; k < n; ++k) {
      // Include sync bytes on purpose: a lone '.' or ".1" with non-zero reserved bytes must not
      // derail the search.
      const std::uint8_t pool[] = {kSync0, kSync1, 0x00, 0x55, 0xFF, static_cast<std::uint8_t>(rng())};
      mixed.push_back(pool[rng() % 6]);
    }
    garbage += n;
    mixed.insert(mixed.end(), s.bytes.begin() + static_cast<std::ptrdiff_t>(at),
                 s.bytes.begin() + static_cast<std::ptrdiff_t>(at + size));
    at += size;
  }
  const Result clean = decode_all(s.bytes);
  const Result r = decode_all(mixed);
  EXPECT_EQ(r.counters.frames, s.frame_sizes.size());
  EXPECT_EQ(r.counters.skipped_bytes, garbage);
  EXPECT_EQ(r.counters.bytes, mixed.size());
  EXPECT_EQ(r.measurements.size(), clean.measurements.size());
}

TEST(FeRobustness, TruncationAtEveryLength) {
  const Stream s = sample_stream(5);
  std::vector<std::size_t> ends;  // cumulative frame ends
  std::size_t total = 0;
  for (std::size_t size : s.frame_sizes) ends.push_back(total += size);
  for (std::size_t len = 0; len <= s.bytes.size(); ++len) {
    const Result r = decode_all(std::span(s.bytes).first(len));
    std::size_t complete = 0, framed = 0;
    for (std::size_t e : ends) {
      if (e <= len) {
        ++complete;
        framed = e;
      }
    }
    ASSERT_EQ(r.counters.frames, complete) << len;
    ASSERT_EQ(r.counters.skipped_bytes, len - framed) << len;  // the incomplete tail
    ASSERT_EQ(r.counters.bad_frames, 0u) << len;
  }
}

TEST(FeRobustness, EverySingleBitFlipLosesOnlyThatFrame) {
  const Stream s = sample_stream(1);  // IMU, Pose, PoseAux, GNSSInfo
  ASSERT_EQ(s.frame_sizes.size(), 4u);
  const std::size_t victim_start = s.frame_sizes[0];
  const std::size_t victim_size = s.frame_sizes[1];  // the Pose
  for (std::size_t byte = victim_start; byte < victim_start + victim_size; ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      std::vector<std::uint8_t> b = s.bytes;
      b[byte] ^= static_cast<std::uint8_t>(1u << bit);
      const Result r = decode_all(b);
      // CRC-32 detects every single-bit error; a flip in the sync, reserved or size field makes
      // the candidate fail earlier. Either way the other three frames survive.
      ASSERT_EQ(r.counters.frames, 3u) << byte << ":" << bit;
      ASSERT_EQ(r.counters.skipped_bytes, victim_size) << byte << ":" << bit;
      ASSERT_LE(r.counters.bad_frames, 1u);
    }
  }
}

TEST(FeRobustness, AbsurdPayloadSizesDoNotStallTheStream) {
  const Stream s = sample_stream(2);
  for (std::uint32_t size : {0xFFFFFFFFu, kMaxPayloadSize + 1, 0x7FFFFFFFu}) {
    std::vector<std::uint8_t> b(kHeaderSize, 0);
    b[0] = kSync0;
    b[1] = kSync1;
    b[kPayloadSizeOffset] = static_cast<std::uint8_t>(size);
    b[kPayloadSizeOffset + 1] = static_cast<std::uint8_t>(size >> 8);
    b[kPayloadSizeOffset + 2] = static_cast<std::uint8_t>(size >> 16);
    b[kPayloadSizeOffset + 3] = static_cast<std::uint8_t>(size >> 24);
    b.insert(b.end(), s.bytes.begin(), s.bytes.end());
    FusionEngineDecoder d;
    test::CollectingSink sink;
    d.feed(b, sink);
    // Rejected at once (no waiting for gigabytes): the frames behind it decode before finish().
    EXPECT_EQ(d.counters().frames, s.frame_sizes.size());
    EXPECT_EQ(d.counters().bad_frames, 1u);
    EXPECT_EQ(d.counters().skipped_bytes, kHeaderSize);
  }
}

TEST(FeRobustness, UnknownTypeClaimingMoreThanItsBoundIsRejectedBeforeAnyCrc) {
  // A corrupted header naming a type the catalogue does not know, with 1 MiB of payload: the
  // framer must not wait for (and CRC) a megabyte before it resynchronises (issue 15.11).
  constexpr std::uint16_t kUnknownType = 0x7FF0;
  ASSERT_FALSE(message_name(kUnknownType).has_value());
  ASSERT_EQ(max_payload_size(kUnknownType), kMaxUnknownPayloadSize);
  const Stream s = sample_stream(2);
  for (const std::uint32_t size : {kMaxUnknownPayloadSize + 1, std::uint32_t{1} << 20}) {
    std::vector<std::uint8_t> b(kHeaderSize, 0);
    b[0] = kSync0;
    b[1] = kSync1;
    b[kMessageTypeOffset] = static_cast<std::uint8_t>(kUnknownType);
    b[kMessageTypeOffset + 1] = static_cast<std::uint8_t>(kUnknownType >> 8);
    for (int i = 0; i < 4; ++i) b[kPayloadSizeOffset + i] = static_cast<std::uint8_t>(size >> (8 * i));
    b.insert(b.end(), s.bytes.begin(), s.bytes.end());
    FusionEngineDecoder d;
    test::CollectingSink sink;
    d.feed(b, sink);
    EXPECT_EQ(d.counters().frames, s.frame_sizes.size()) << size;  // before finish(): nothing waited for
    EXPECT_EQ(d.counters().bad_frames, 1u);
    EXPECT_EQ(d.counters().skipped_bytes, kHeaderSize);
  }
}

TEST(FeRobustness, CorruptedLengthNearTheEndDoesNotHideLaterFrames) {
  // A plausible but wrong payload size in the second frame: the framer waits for bytes that
  // never come; at finish() it rescans and recovers every frame after it.
  const Stream s = sample_stream(4);
  std::vector<std::uint8_t> b = s.bytes;
  const std::size_t second = s.frame_sizes[0];
  b[second + kPayloadSizeOffset + 2] = 0x01;  // +65536 bytes
  const Result r = decode_all(b);
  EXPECT_EQ(r.counters.frames, s.frame_sizes.size() - 1);
  EXPECT_EQ(r.counters.skipped_bytes, s.frame_sizes[1]);
}

TEST(FeRobustness, ChunkedFeedingEqualsOneFeed) {
  const Stream s = sample_stream(40);
  std::vector<std::uint8_t> b = s.bytes;
  std::mt19937_64 rng(99);
  for (int k = 0; k < 30; ++k) b[rng() % b.size()] ^= static_cast<std::uint8_t>(rng());  // some damage
  const Result whole = decode_all(b);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<std::size_t> cuts;
    std::size_t at = 0;
    while (true) {
      at += 1 + rng() % (trial < 10 ? 3 : 300);
      if (at >= b.size()) break;
      cuts.push_back(at);
    }
    const Result r = decode_chunks(b, cuts);
    ASSERT_TRUE(same_counters(r.counters, whole.counters)) << trial;
    ASSERT_EQ(r.measurements.size(), whole.measurements.size());
    for (std::size_t i = 0; i < r.measurements.size(); ++i) {
      ASSERT_EQ(kind_of(r.measurements[i]), kind_of(whole.measurements[i]));
      ASSERT_EQ(header_of(r.measurements[i]).time_ns, header_of(whole.measurements[i]).time_ns);
    }
  }
}

TEST(FeStreamDecoder, CountersAndMeasurementCountsEqualWhatWasWritten) {
  // A known mix: 50 IMU, 10 solutions (Pose+PoseAux+GNSSInfo), 5 headings, 7 wheel speeds,
  // 3 vehicle speeds, 4 tick messages, 6 GNSS fixes (3 positions + 3 velocities), then one
  // frame with a corrupted CRC, one frame of an undefined type and 100 bytes of garbage.
  FusionEngineEncoder enc;
  std::vector<std::uint8_t> b;
  std::uint64_t frames = 0;
  auto put = [&](const Measurement& m, int n_frames) {
    ASSERT_TRUE(enc.encode(m, b));
    frames += static_cast<std::uint64_t>(n_frames);
  };
  for (int i = 0; i < 50; ++i) {
    ImuSample imu;
    imu.header = {kT0 + std::int64_t{i} * 1'000'000, TimeSource::kGps, 0, ImuSample::kValidAccel};
    imu.frame = i % 2 ? SensorFrame::kVehicle : SensorFrame::kSensor;
    put(imu, 1);
    if (i % 5 == 0) {
      NavSolution s;
      s.header = {kT0 + std::int64_t{i} * 1'000'000, TimeSource::kGps, 0, NavSolution::kValidPosition};
      s.mode = NavMode::kNavigation;
      s.gnss_fix = GnssFixType::kDgnss;
      put(s, 3);
    }
  }
  for (int i = 0; i < 5; ++i) put(GnssHeading{{kT0, TimeSource::kGps, 0, GnssHeading::kValidHeading}}, 1);
  for (int i = 0; i < 7; ++i) put(WheelSpeeds{{kT0, TimeSource::kGps, 0, WheelSpeeds::kValidRearLeft}}, 1);
  for (int i = 0; i < 3; ++i) put(VehicleSpeed{{kT0, TimeSource::kGps, 0, VehicleSpeed::kValidSpeed}}, 1);
  for (int i = 0; i < 4; ++i) {
    WheelTicks t;
    t.header = {kT0, TimeSource::kGps, 0, WheelTicks::kValidFrontLeft};
    t.channels = i % 2 ? 1 : 4;
    put(t, 1);
  }
  for (int i = 0; i < 3; ++i) {
    GnssPosition p;
    p.header = {kT0, TimeSource::kGps, 0, GnssPosition::kValidPosition};
    put(p, 1);
    GnssVelocity v;
    v.header = {kT0, TimeSource::kGps, 0, GnssVelocity::kValidVelocity};
    put(v, 1);
  }
  EXPECT_FALSE(enc.encode(ExternalHeading{}, b));  // no FusionEngine message for it
  const std::size_t good_bytes = b.size();
  FusionEngineWriter w;
  std::vector<std::uint8_t> bad = w.frame(CommandResponseMessage{7, 0});
  bad[kHeaderSize] ^= 0x01;  // payload damage: CRC fails
  std::vector<std::uint8_t> unknown;
  const std::size_t start = begin_frame(unknown, 65000, 0, 0, kSourceIdInvalid);
  unknown.insert(unknown.end(), 8, 0x42);
  end_frame(unknown, start);
  b.insert(b.end(), bad.begin(), bad.end());
  b.insert(b.end(), unknown.begin(), unknown.end());
  b.insert(b.end(), 100, 0x00);

  FusionEngineDecoder d;
  test::CollectingSink sink;
  d.feed(b, sink);
  d.finish(sink);
  const auto& c = d.counters();
  EXPECT_EQ(c.bytes, b.size());
  EXPECT_EQ(c.frames, frames + 1);  // + the unknown-type frame
  EXPECT_EQ(c.bad_frames, 1u);
  EXPECT_EQ(c.skipped_bytes, bad.size() + 100);
  EXPECT_EQ(c.unknown_frames, 1u);
  EXPECT_EQ(c.decode_errors, 0u);
  EXPECT_EQ(d.framer().framed_bytes(), good_bytes + unknown.size());
  EXPECT_EQ(sink.count(MeasurementKind::kImu), 50u);
  EXPECT_EQ(sink.count(MeasurementKind::kDeviceSolution), 10u);
  EXPECT_EQ(sink.count(MeasurementKind::kGnssHeading), 5u);
  EXPECT_EQ(sink.count(MeasurementKind::kWheelSpeed), 7u);
  EXPECT_EQ(sink.count(MeasurementKind::kVehicleSpeed), 3u);
  EXPECT_EQ(sink.count(MeasurementKind::kWheelTicks), 4u);
  EXPECT_EQ(sink.count(MeasurementKind::kGnssPosition), 3u);
  EXPECT_EQ(sink.count(MeasurementKind::kGnssVelocity), 3u);
  EXPECT_EQ(sink.measurements.size(), 85u);
}

}  // namespace
}  // namespace navfuse::frontends::fusionengine

// Randomised round trips of every message in the catalogue (digest §3, 52 types): random field
// values -> FusionEngineWriter -> Framer -> decode -> the same fields and the same bytes again.
// The byte layout itself is pinned by the digest examples, the capture and the layout sizes
// below (digest §3 "Fixed payload" column).
#include <gtest/gtest.h>

#include <random>
#include <tuple>

#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/record_builder.hpp"
#include "random_fill.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

template <class M>
frontends::FrameRecord record_of(M msg) {
  frontends::FrameRecord rec;
  RecordBuilder rb(rec);
  msg.visit(rb);
  return rec;
}

// The fixed part of each layout, as the digest's catalogue lists it.
TEST(FeMessageLayouts, FixedSizesMatchTheDigestCatalogue) {
  std::apply(
      [](auto... m) {
        (
            [&](auto msg) {
              using M = decltype(msg);
              if constexpr (requires { msg.sync_lengths(); }) msg.sync_lengths();
              std::vector<std::uint8_t> bytes;
              PayloadWriter w(bytes);
              msg.visit(w);
              if constexpr (requires { msg.padding(); }) bytes.resize(bytes.size() + msg.padding());
              EXPECT_EQ(bytes.size(), M::kSize) << M::kName;
            }(m),
            ...);
      },
      AllMessages{});
  EXPECT_EQ(kCatalogSize, 52u);
  EXPECT_EQ(PoseMessage::kSize, 140u);
  EXPECT_EQ(GnssAttitudeOutputMessage::kSize, 60u);  // u32 flags, digest §13 A2
  EXPECT_EQ(EventNotificationMessage::kSize, 24u);   // reserved2[2], digest §13 A5
  EXPECT_EQ(HardwareTickConfig::kSize, 8u);          // digest §13 A3
  EXPECT_EQ(ImportDataMessage::kSize, 16u);          // 4-byte DataVersion, digest §13 A4
}

TEST(FeMessageRoundTrip, EveryCatalogueTypeRandomised) {
  std::mt19937_64 rng(20261121);
  FusionEngineWriter writer;
  std::vector<std::uint8_t> stream;
  std::size_t written = 0;
  for (int iteration = 0; iteration < 40; ++iteration) {
    std::apply(
        [&](auto... m) {
          (
              [&](auto msg) {
                using M = decltype(msg);
                test::RandomFill fill(rng);
                msg.visit(fill);
                if constexpr (requires { msg.sync_lengths(); }) msg.sync_lengths();
                const std::uint32_t sequence = writer.next_sequence();
                const std::vector<std::uint8_t> bytes = writer.frame(msg);
                stream.insert(stream.end(), bytes.begin(), bytes.end());
                ++written;

                const auto frames = test::frames_of(bytes);
                ASSERT_EQ(frames.size(), 1u) << M::kName;
                const Header& h = frames[0].header;
                EXPECT_EQ(h.message_type, to_u16(M::kType));
                EXPECT_EQ(h.message_version, M::kVersion);
                EXPECT_EQ(h.sequence, sequence);
                EXPECT_EQ(h.source_id, default_source_id(to_u16(M::kType)));
                M decoded;
                ASSERT_TRUE(decode_payload(frames[0].view().payload, decoded)) << M::kName;
                EXPECT_EQ(record_of(decoded).fields, record_of(msg).fields) << M::kName;
                const auto again = test::reencode(frames[0].view());
                ASSERT_TRUE(again);
                EXPECT_EQ(*again, bytes) << M::kName;
              }(m),
              ...);
        },
        AllMessages{});
  }
  // The whole stream through the StreamDecoder: every frame valid, known and decodable.
  FusionEngineDecoder decoder;
  test::CollectingSink sink;
  decoder.feed(stream, sink);
  decoder.finish(sink);
  EXPECT_EQ(decoder.counters().frames, written);
  EXPECT_EQ(decoder.counters().bad_frames, 0u);
  EXPECT_EQ(decoder.counters().skipped_bytes, 0u);
  EXPECT_EQ(decoder.counters().unknown_frames, 0u);
  EXPECT_EQ(decoder.counters().decode_errors, 0u);
}

TEST(FeMessageRoundTrip, SourceIdentifierFollowsSpecRule) {
  // Spec L193: 0 for measurement input messages, 0xFFFFFFFF for the rest.
  EXPECT_EQ(default_source_id(to_u16(MessageType::kImuInput)), 0u);
  EXPECT_EQ(default_source_id(to_u16(MessageType::kWheelSpeedInput)), 0u);
  EXPECT_EQ(default_source_id(to_u16(MessageType::kVehicleTickInput)), 0u);
  EXPECT_EQ(default_source_id(to_u16(MessageType::kPose)), 0xFFFFFFFFu);
  EXPECT_EQ(default_source_id(to_u16(MessageType::kResetRequest)), 0xFFFFFFFFu);
}

TEST(FeMessageRoundTrip, VersionInfoIsPaddedToFourBytes) {
  // Spec L2611: "padded to a length that is a multiple of 4 bytes".
  VersionInfoMessage v;
  v.fw_version = "1.2.3";   // 5
  v.engine_version = "ab";  // 2 -> 16 + 7 = 23 -> 1 byte of padding
  FusionEngineWriter w;
  const auto& bytes = w.frame(v);
  EXPECT_EQ(bytes.size(), kHeaderSize + 24);
  EXPECT_EQ(bytes.back(), 0);
}

TEST(FeMessageRoundTrip, LargerPayloadOfANewerVersionDecodesItsKnownPrefix) {
  // Spec L189: a newer version extends the message; the known prefix must still decode.
  PoseMessage pose;
  pose.solution_type = static_cast<std::uint8_t>(SolutionType::kAutonomousGps);
  pose.lla_deg = {12.5, -3.25, 100.0};
  std::vector<std::uint8_t> payload;
  PayloadWriter pw(payload);
  pose.visit(pw);
  payload.insert(payload.end(), 13, 0xAB);  // 13 unknown extra bytes, not a multiple of 4
  std::vector<std::uint8_t> stream;
  const std::size_t start = begin_frame(stream, to_u16(MessageType::kPose), 7, 0, kSourceIdInvalid);
  stream.insert(stream.end(), payload.begin(), payload.end());
  end_frame(stream, start);
  FusionEngineDecoder decoder;
  test::CollectingSink sink;
  decoder.feed(stream, sink);
  decoder.finish(sink);
  EXPECT_EQ(decoder.counters().frames, 1u);
  EXPECT_EQ(decoder.counters().decode_errors, 0u);
  ASSERT_EQ(sink.all<NavSolution>().size(), 1u);
  EXPECT_EQ(sink.all<NavSolution>()[0].height_m, 100.0);
}

TEST(FeMessageRoundTrip, ShortPayloadIsADecodeErrorNotACrash) {
  std::vector<std::uint8_t> stream;
  const std::size_t start = begin_frame(stream, to_u16(MessageType::kPose), 2, 0, kSourceIdInvalid);
  stream.insert(stream.end(), 100, 0);  // Pose needs 140
  end_frame(stream, start);
  const std::size_t start2 = begin_frame(stream, 12345, 0, 1, kSourceIdInvalid);  // not in the catalogue
  stream.insert(stream.end(), 8, 0);
  end_frame(stream, start2);
  FusionEngineDecoder decoder;
  test::CollectingSink sink(true);
  decoder.feed(stream, sink);
  decoder.finish(sink);
  EXPECT_EQ(decoder.counters().frames, 2u);
  EXPECT_EQ(decoder.counters().decode_errors, 1u);
  EXPECT_EQ(decoder.counters().unknown_frames, 1u);
  EXPECT_TRUE(sink.measurements.empty());
  ASSERT_EQ(sink.records.size(), 2u);
  EXPECT_EQ(sink.records[1].name, "Unknown(12345)");
}

}  // namespace
}  // namespace navfuse::frontends::fusionengine

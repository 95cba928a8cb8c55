// Every complete hex message of the spec (digest §12.1 E1-E14, spec lines cited per case) and
// the digest's derived vectors (§12.3): each frames with the CRC the digest recomputed, decodes
// to the values the spec text states, and re-encodes to identical bytes.
#include <gtest/gtest.h>

#include <cmath>

#include "core/bytes/checks.hpp"
#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/payload_reader.hpp"
#include "frontends/fusionengine/writer.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

using test::from_hex;

// Frames `bytes`, expecting exactly one frame; returns it (payload copied out).
struct OneFrame {
  Header header;
  std::vector<std::uint8_t> payload;
};
OneFrame frame_one(const std::vector<std::uint8_t>& bytes) {
  Framer framer;
  OneFrame out;
  int frames = 0;
  framer.feed(bytes, [&](const Frame& f) {
    ++frames;
    out.header = f.header;
    out.payload.assign(f.payload.begin(), f.payload.end());
  });
  framer.finish([](const Frame&) {});
  EXPECT_EQ(frames, 1);
  EXPECT_EQ(framer.counters().bad_frames, 0u);
  EXPECT_EQ(framer.counters().skipped_bytes, 0u);
  return out;
}

template <class M>
M decode_one(const std::vector<std::uint8_t>& bytes, std::uint32_t expected_crc) {
  const OneFrame f = frame_one(bytes);
  EXPECT_EQ(f.header.crc, expected_crc);
  EXPECT_EQ(f.header.message_type, to_u16(M::kType));
  EXPECT_EQ(f.header.protocol_version, 2);
  EXPECT_EQ(f.header.message_version, 0);
  EXPECT_EQ(f.header.sequence, 0u);
  EXPECT_EQ(f.header.source_id, 0u);
  M msg;
  EXPECT_TRUE(decode_payload(f.payload, msg));
  return msg;
}

// The spec examples all use sequence 0 and source identifier 0 (digest §12.1, §13 A14).
template <class M>
void expect_reencodes(const M& msg, const std::vector<std::uint8_t>& expected) {
  FusionEngineWriter writer;
  EXPECT_EQ(writer.frame(msg, FrameOptions::with_source_id(0)), expected);
}

TEST(FeDigestExamples, CrcCheckValue) {
  // Digest §1.4 / §12.3: the standard CRC-32 check value.
  EXPECT_EQ(bytes::crc32(bytes::as_bytes("123456789")), 0xCBF43926u);
}

TEST(FeDigestExamples, E1ResetColdStartHexCarriesGnssReboot) {
  // Spec L782-788: the hex carries 0x01000FFF (digest §13 A7), whatever the text says.
  const auto bytes = from_hex("2e31 0000 0acf ee8f 0200 ca32 0000 0000 0400 0000 0000 0000 ff0f 0001");
  const auto m = decode_one<ResetRequestMessage>(bytes, 0x8FEECF0Au);
  EXPECT_EQ(m.reset_mask, reset::kColdStart | reset::kRebootGnssMeasurementEngine);
  expect_reencodes(m, bytes);
}

TEST(FeDigestExamples, E1AsTheTextDescribesItFailsItsCrc) {
  // The text's mask 0x00000FFF with the printed CRC is not a valid frame: the framer must reject
  // it for its checksum and frame nothing.
  auto bytes = from_hex("2e31 0000 0acf ee8f 0200 ca32 0000 0000 0400 0000 0000 0000 ff0f 0000");
  Framer framer;
  int frames = 0;
  framer.feed(bytes, [&](const Frame&) { ++frames; });
  framer.finish([&](const Frame&) { ++frames; });
  EXPECT_EQ(frames, 0);
  EXPECT_EQ(framer.counters().bad_frames, 1u);
  EXPECT_EQ(framer.counters().skipped_bytes, bytes.size());
}

TEST(FeDigestExamples, E2FactoryReset) {
  const auto bytes = from_hex("2e31 0000 b39e 0bf3 0200 ca32 0000 0000 0400 0000 0000 0000 ffff ffff");
  const auto m = decode_one<ResetRequestMessage>(bytes, 0xF30B9EB3u);
  EXPECT_EQ(m.reset_mask, reset::kFactoryReset);
  expect_reencodes(m, bytes);
}

TEST(FeDigestExamples, E3ShutdownStopEngine) {
  const auto bytes = from_hex(
      "2e31 0000 716f 5414 0200 cd32 0000 0000 1000 0000 0000 0000 0000 0000 0000 0000 0000 0000 0000 0000");
  const auto m = decode_one<ShutdownRequestMessage>(bytes, 0x14546F71u);
  EXPECT_EQ(m.flags, 0u);
  expect_reencodes(m, bytes);
}

TEST(FeDigestExamples, E4FaultControlCrash) {
  const auto bytes = from_hex(
      "2e31 0000 bde4 777b 0200 ce32 0000 0000 1400 0000 0000 0000 0100 0000 0000 0000 0000 0000 0000 0000 "
      "0000 0000");
  const auto m = decode_one<FaultControlMessage>(bytes, 0x7B77E4BDu);
  EXPECT_EQ(m.fault_type, 1);  // Crash (L851)
  EXPECT_EQ(m.value_length, 0u);
  expect_reencodes(m, bytes);
}

TEST(FeDigestExamples, E5FaultControlCocomAltitudeIs45Bytes) {
  // L889-894: payload 21 bytes, not a multiple of 4 (digest §13 A1): must be accepted.
  const auto bytes = from_hex(
      "2e31 0000 0bf7 0344 0200 ce32 0000 0000 1500 0000 0000 0000 0300 0000 0000 0000 0000 0000 0000 0000 "
      "0100 0000 03");
  ASSERT_EQ(bytes.size(), 45u);
  const auto m = decode_one<FaultControlMessage>(bytes, 0x4403F70Bu);
  EXPECT_EQ(m.fault_type, 3);  // COCOM
  ASSERT_EQ(m.value.size(), 1u);
  EXPECT_EQ(m.value[0], 3);  // ALTITUDE
  expect_reencodes(m, bytes);
}

TEST(FeDigestExamples, E6SetOutputLeverArm) {
  const auto bytes = from_hex(
      "2e31 0000 8cd8 859a 0200 2c33 0000 0000 1400 0000 0000 0000 1300 0000 0c00 0000 9a99 193f 0000 0000 "
      "9a99 993f");
  const auto m = decode_one<SetConfigMessage>(bytes, 0x9A85D88Cu);
  EXPECT_EQ(m.config_type, to_u16(ConfigType::kOutputLeverArm));
  EXPECT_EQ(m.flags, 0);
  const auto arm = parse_config<Point3f>(m.value);
  ASSERT_TRUE(arm);
  EXPECT_EQ(arm->xyz_m[0], 0.6f);  // "[0.6, 0.0, 1.2]" (L1011)
  EXPECT_EQ(arm->xyz_m[1], 0.0f);
  EXPECT_EQ(arm->xyz_m[2], 1.2f);
  expect_reencodes(m, bytes);
  // Built from the typed value, the same bytes come out.
  SetConfigMessage built;
  built.config_type = to_u16(ConfigType::kOutputLeverArm);
  built.value = pack_config(Point3f{{0.6f, 0.0f, 1.2f}});
  expect_reencodes(built, bytes);
}

TEST(FeDigestExamples, E7SetOrientationLeftAndSave) {
  const auto bytes = from_hex("2e31 0000 0ac0 a42c 0200 2c33 0000 0000 0c00 0000 0000 0000 1100 0100 0400 0000 0204 0000");
  const auto m = decode_one<SetConfigMessage>(bytes, 0x2CA4C00Au);
  EXPECT_EQ(m.config_type, to_u16(ConfigType::kDeviceCoarseOrientation));
  EXPECT_EQ(m.flags, kConfigFlagApplyAndSave);
  const auto o = parse_config<CoarseOrientation>(m.value);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->x_direction, static_cast<std::uint8_t>(Direction::kLeft));
  EXPECT_EQ(o->z_direction, static_cast<std::uint8_t>(Direction::kUp));
  expect_reencodes(m, bytes);
}

TEST(FeDigestExamples, E8SetUart1Baud) {
  const auto bytes = from_hex("2e31 0000 61ad a75c 0200 2c33 0000 0000 0c00 0000 0000 0000 0001 0100 0400 0000 00c2 0100");
  const auto m = decode_one<SetConfigMessage>(bytes, 0x5CA7AD61u);
  EXPECT_EQ(m.config_type, to_u16(ConfigType::kUart1BaudRate));
  const auto baud = parse_config<ScalarConfig<std::uint32_t>>(m.value);
  ASSERT_TRUE(baud);
  EXPECT_EQ(baud->value, 115200u);
  expect_reencodes(m, bytes);
}

TEST(FeDigestExamples, E9E10SaveConfig) {
  const auto save = from_hex("2e31 0000 c48c 1ee8 0200 2e33 0000 0000 0400 0000 0000 0000 0000 0000");
  const auto m9 = decode_one<SaveConfigMessage>(save, 0xE81E8CC4u);
  EXPECT_EQ(m9.action, static_cast<std::uint8_t>(SaveAction::kSave));
  expect_reencodes(m9, save);
  const auto revert = from_hex("2e31 0000 4f44 1742 0200 2e33 0000 0000 0400 0000 0000 0000 0200 0000");
  const auto m10 = decode_one<SaveConfigMessage>(revert, 0x4217444Fu);
  EXPECT_EQ(m10.action, static_cast<std::uint8_t>(SaveAction::kRevertToDefault));
  expect_reencodes(m10, revert);
}

struct RateCase {
  const char* hex;
  std::uint32_t crc;
  std::uint8_t iface_type, iface_index, protocol, flags;
  std::uint16_t message_id;
  std::uint8_t rate;
};

TEST(FeDigestExamples, E11ToE14SetMessageRate) {
  const RateCase cases[] = {
      // E11 L1490-1497: Pose at max rate (on change) on UART1.
      {"2e31 0000 6a84 7724 0200 a433 0000 0000 0c00 0000 0000 0000 0101 0000 0100 1027 0100 0000", 0x2477846Au,
       1, 1, 1, 0, 10000, 1},
      // E12 L1500-1505: the same, applied and saved.
      {"2e31 0000 de8f 0082 0200 a433 0000 0000 0c00 0000 0000 0000 0101 0000 0101 1027 0100 0000", 0x82008FDEu,
       1, 1, 1, 1, 10000, 1},
      // E13 L1508-1513: everything on every interface back to the default, incl. disabled.
      {"2e31 0000 aa8d 150d 0200 a433 0000 0000 0c00 0000 0000 0000 ff00 0000 ff02 ffff ff00 0000", 0x0D158DAAu,
       0xFF, 0, 0xFF, 2, 0xFFFF, 0xFF},
      // E14 L1518-1523: all enabled NMEA messages on UART1 at 1 Hz.
      {"2e31 0000 a936 db31 0200 a433 0000 0000 0c00 0000 0000 0000 0101 0000 0200 ffff 0900 0000", 0x31DB36A9u,
       1, 1, 2, 0, 0xFFFF, 9},
  };
  for (const auto& c : cases) {
    const auto bytes = from_hex(c.hex);
    const auto m = decode_one<SetMessageRateMessage>(bytes, c.crc);
    EXPECT_EQ(m.output_interface.type, c.iface_type);
    EXPECT_EQ(m.output_interface.index, c.iface_index);
    EXPECT_EQ(m.protocol, c.protocol);
    EXPECT_EQ(m.flags, c.flags);
    EXPECT_EQ(m.message_id, c.message_id);
    EXPECT_EQ(m.rate, c.rate);
    expect_reencodes(m, bytes);
  }
}

TEST(FeDigestExamples, DerivedColdStartVectorsAndSourceIdRule) {
  // Digest §12.3: COLD_START 0x00000FFF with source 0, and with 0xFFFFFFFF, the spec's value for
  // non-measurement messages (L193) and the writer's default for commands.
  const auto src0 = from_hex("2e31 0000 9cff e9f8 0200 ca32 0000 0000 0400 0000 0000 0000 ff0f 0000");
  const auto src_invalid = from_hex("2e31 0000 0adf 3462 0200 ca32 0000 0000 0400 0000 ffff ffff ff0f 0000");
  ResetRequestMessage cold;
  cold.reset_mask = reset::kColdStart;
  FusionEngineWriter w0;
  EXPECT_EQ(w0.frame(cold, FrameOptions::with_source_id(0)), src0);
  FusionEngineWriter w1;
  EXPECT_EQ(w1.frame(cold), src_invalid);
  EXPECT_EQ(frame_one(src_invalid).header.crc, 0x6234DF0Au);
}

}  // namespace
}  // namespace navfuse::frontends::fusionengine

// The binary worked examples of the digest §9.1 (ICD Appendix A, Fig A.2/A.3, B.1) and the
// derived vectors of §9.2: they decode to the stated values and re-encode to the same bytes.
#include <gtest/gtest.h>

#include <cmath>

#include "core/bytes/checks.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/vectornav/binary_codec.hpp"
#include "frontends/vectornav/binary_header.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::vectornav {
namespace {

using test::from_hex;

// Digest §9.1 TV-B1 (ICD L5252-5262) and TV-B2 (L5270-5285); §9.2 TV-D1..D3.
const char* const kFigA2 = "FA 01 08 00 93 50 2E 42 83 3E F1 3F 48 B5 04 BB 92 88";
const char* const kFigA3 = "FA 05 08 00 10 00 42 8E E7 C2 1E 12 11 C1 FF 49 9C 40 E3 27 C4 41 6A 4E";
const char* const kTvD1 = "FA 90 10 00 01 10 80 02 00 00 00 00 3F 00 00 80 3E 00 00 00 3E 03 17 01 AD DE";
const char* const kTvD2 =
    "FA 11 09 00 00 01 00 CA 9A 3B 00 00 00 00 93 50 2E 42 81 3E F1 3F DD B5 04 BB 00 00 80 3F 00 00 00 3F 00 00 00 "
    "3F 0A 75";
const char* const kTvD3 =
    "FA 08 A6 40 A8 FE 66 03 F8 C7 01 00 FF 08 D2 71 35 B2 2B 72 40 40 C5 C2 B5 7F 0A 2D 58 C0 37 89 41 60 E5 74 64 "
    "40 0A D7 A3 BB 0A D7 A3 3B 1B 2F DD 3D 02 00 00 05 1F 2D 07 3C 7B 00 06 0C 15 26 04 0F D8 FF 8A 91";

// Decodes a single-packet vector and checks that the framer accepts exactly it.
BinaryMessage decode_packet(const std::vector<std::uint8_t>& packet) {
  BinaryMessage m;
  EXPECT_EQ(bytes::crc16_xmodem(std::span(packet).subspan(1)), 0) << "CRC residual must be 0 (L5250)";
  EXPECT_TRUE(decode_binary_body(std::span(packet).subspan(1, packet.size() - 3), m));
  return m;
}

std::vector<std::uint8_t> reencode(BinaryMessage m) {
  std::vector<std::uint8_t> out;
  EXPECT_TRUE(append_binary_message(m, out));
  return out;
}

TEST(VnSpecVectors, Crc16CheckValueAndFigureCrcs) {
  EXPECT_EQ(bytes::crc16_xmodem(bytes::as_bytes("123456789")), 0x31C3);  // digest §2.3
  const auto a2 = from_hex(kFigA2);
  EXPECT_EQ(bytes::crc16_xmodem(std::span(a2).subspan(1, a2.size() - 3)), 0x9288);
  const auto a3 = from_hex(kFigA3);
  EXPECT_EQ(bytes::crc16_xmodem(std::span(a3).subspan(1, a3.size() - 3)), 0x6A4E);
}

// The ICD's reference algorithm (L624-639), byte-swap form, as an independent check of the
// table-driven core implementation over random data, lengths and initial values.
std::uint16_t icd_crc16(std::span<const std::uint8_t> data, std::uint16_t crc) {
  for (std::uint8_t b : data) {
    crc = static_cast<std::uint16_t>((crc >> 8) | (crc << 8));
    crc ^= b;
    crc ^= static_cast<std::uint16_t>((crc & 0xFF) >> 4);
    crc ^= static_cast<std::uint16_t>(crc << 12);
    crc ^= static_cast<std::uint16_t>((crc & 0x00FF) << 5);
  }
  return crc;
}

TEST(VnSpecVectors, Crc16MatchesTheIcdReferenceCode) {
  std::uint64_t x = 88172645463325252ull;
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<std::uint8_t> data(static_cast<std::size_t>(trial % 67));
    for (auto& b : data) {
      x ^= x << 13, x ^= x >> 7, x ^= x << 17;
      b = static_cast<std::uint8_t>(x);
    }
    const auto init = static_cast<std::uint16_t>(x >> 20);
    ASSERT_EQ(bytes::crc16_xmodem(data, init), icd_crc16(data, init)) << trial;
  }
}

TEST(VnSpecVectors, FigA2CommonYpr) {
  const auto packet = from_hex(kFigA2);
  const BinaryMessage m = decode_packet(packet);
  EXPECT_EQ(m.header.types[kSlotCommon], 1u << common_type::kYpr);
  EXPECT_FLOAT_EQ(m.attitude.ypr_deg[0], 43.57868576049805f);
  EXPECT_FLOAT_EQ(m.attitude.ypr_deg[1], 1.8847202062606812f);
  EXPECT_FLOAT_EQ(m.attitude.ypr_deg[2], -0.0020249653607606888f);
  EXPECT_EQ(reencode(m), packet);

  // Through the stream decoder: one frame, one device solution with that attitude.
  VnStreamDecoder d;
  test::CollectingSink sink(true);
  test::decode_all(d, packet, sink);
  EXPECT_EQ(d.counters().frames, 1u);
  ASSERT_EQ(sink.count(MeasurementKind::kDeviceSolution), 1u);
  const auto& s = std::get<NavSolution>(sink.measurements[0]);
  EXPECT_NEAR(s.rpy_rad.z(), 43.578686 * rot::kDegToRad, 1e-6);
  EXPECT_NEAR(s.rpy_rad.y(), 1.884720 * rot::kDegToRad, 1e-6);
  EXPECT_NEAR(s.rpy_rad.x(), -0.002025 * rot::kDegToRad, 1e-6);
  ASSERT_EQ(sink.records.size(), 1u);
  const FieldValue* yaw = test::field(sink.records[0], "common.yaw_deg");
  ASSERT_NE(yaw, nullptr);
  EXPECT_NEAR(std::get<double>(*yaw), 43.578686, 1e-6);
}

TEST(VnSpecVectors, FigA3CommonYprAndImuTemperature) {
  const auto packet = from_hex(kFigA3);
  const BinaryMessage m = decode_packet(packet);
  EXPECT_EQ(m.header.groups, 0x05u);
  EXPECT_EQ(m.header.types[kSlotImu], 1u << imu_type::kTemperature);
  EXPECT_FLOAT_EQ(m.attitude.ypr_deg[0], -115.77784729003906f);
  EXPECT_NEAR(m.attitude.ypr_deg[1], -9.066923, 1e-6);
  EXPECT_FLOAT_EQ(m.attitude.ypr_deg[2], 4.884032726287842f);
  EXPECT_NEAR(m.imu.temperature_c, 24.519476, 1e-5);
  EXPECT_EQ(reencode(m), packet);
}

TEST(VnSpecVectors, TvD1ExtendedHeaderAndGnss3) {
  const auto packet = from_hex(kTvD1);
  const BinaryMessage m = decode_packet(packet);
  // Errata A1: raw numbering. Group byte 2 bit 4 = Gnss3 (group 12); word1 bit 1 = type 17.
  EXPECT_EQ(m.header.groups, (1u << 4) | (1u << 12));
  EXPECT_EQ(m.header.types[kSlotAttitude], 1u << attitude_type::kYprU);
  EXPECT_EQ(m.header.types[kSlotGnss3], (1u << gnss_type::kGnssFix) | (1u << gnss_type::kStatus));
  EXPECT_EQ(m.attitude.ypr_uncertainty_deg, (Vec3f{0.5f, 0.25f, 0.125f}));
  EXPECT_EQ(m.gnss[2].fix, 3);
  EXPECT_EQ(m.gnss[2].gnss_status, 0x0117);
  EXPECT_EQ(reencode(m), packet);
}

TEST(VnSpecVectors, TvD2TimeStartupYprYprU) {
  const auto packet = from_hex(kTvD2);
  const BinaryMessage m = decode_packet(packet);
  EXPECT_EQ(m.time.time_startup_ns, 1'000'000'000u);
  EXPECT_FLOAT_EQ(m.attitude.ypr_deg[0], 43.578686f);
  EXPECT_FLOAT_EQ(m.attitude.ypr_deg[1], 1.884720f);
  EXPECT_FLOAT_EQ(m.attitude.ypr_deg[2], -0.002025f);
  EXPECT_EQ(m.attitude.ypr_uncertainty_deg, (Vec3f{1.0f, 0.5f, 0.5f}));
  EXPECT_EQ(reencode(m), packet);
}

TEST(VnSpecVectors, TvD3GnssWithVariableSatInfo) {
  const auto packet = from_hex(kTvD3);
  const BinaryMessage m = decode_packet(packet);
  const GnssFields& g = m.gnss[0];
  EXPECT_EQ(m.header.types[kSlotGnss1], 0x40A6u);  // the ICD's "0xA640" in wire order (L5291)
  EXPECT_EQ(g.gps_tow_ns, 501342999609000u);
  EXPECT_EQ(g.gps_week, 2303);
  EXPECT_DOUBLE_EQ(g.pos_lla[0], 32.89195850);
  EXPECT_DOUBLE_EQ(g.pos_lla[1], -96.70376580);
  EXPECT_DOUBLE_EQ(g.pos_lla[2], 163.653);
  EXPECT_EQ(g.vel_ned_mps, (Vec3f{-0.005f, 0.005f, 0.108f}));
  ASSERT_EQ(g.sat_info.size(), 2u);
  EXPECT_EQ(g.sat_info[0], (SatInfoEntry{0, 5, 0x1F, 45, 7, 60, 123}));
  EXPECT_EQ(g.sat_info[1], (SatInfoEntry{6, 12, 0x15, 38, 4, 15, -40}));
  EXPECT_EQ(reencode(m), packet);

  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, packet, sink);
  EXPECT_EQ(sink.count(MeasurementKind::kGnssPosition), 1u);
  EXPECT_EQ(sink.count(MeasurementKind::kGnssVelocity), 1u);
  const auto& p = std::get<GnssPosition>(sink.measurements[0]);
  EXPECT_NEAR(p.lat_rad, 32.89195850 * rot::kDegToRad, 1e-12);
  EXPECT_EQ(p.header.time_source, TimeSource::kGps);
  // 2303 weeks + 501342.999609 s after the GPS epoch.
  EXPECT_EQ(p.header.time_ns, 2303LL * 604800 * 1'000'000'000LL + 501342999609000LL);
}

TEST(VnSpecVectors, TvB5ExtensionExampleHeader) {
  // ICD L5379: "FA 90 10 00 01 01 80 02 00 ..." (payload not given). Under raw numbering this is
  // Attitude{YprU} + Gnss3{TimeUtc, GnssStatus} (errata A1).
  const auto bytes = from_hex("90 10 00 01 01 80 02 00");
  BinaryHeader h;
  ASSERT_EQ(parse_header(bytes, h), ParseStatus::kOk);
  EXPECT_EQ(h.header_bytes, bytes.size());
  EXPECT_EQ(h.types[kSlotAttitude], 0x0100u);
  EXPECT_EQ(h.types[kSlotGnss3], (1u << gnss_type::kTimeUtc) | (1u << gnss_type::kStatus));
  std::vector<std::uint8_t> again;
  append_header(h, again);
  EXPECT_EQ(again, bytes);
}

TEST(VnSpecVectors, TvB3AndB4HeadersAndPayloadSizes) {
  // TV-B3 (L5225-5226): group 0x11, words 0x0009 and 0x0100: 8 + 12 + 12 = 32 payload bytes.
  BinaryHeader h;
  ASSERT_EQ(parse_header(from_hex("11 09 00 00 01"), h), ParseStatus::kOk);
  std::size_t payload = 0;
  ASSERT_EQ(measure_payload(h, {}, 1000, payload), ParseStatus::kOk);
  EXPECT_EQ(payload, 32u);
  // TV-B4 (L564-572): Common word 0x0129 = TimeStartup + Ypr + AngularRate + Accel = 44 bytes.
  ASSERT_EQ(parse_header(from_hex("01 29 01"), h), ParseStatus::kOk);
  ASSERT_EQ(measure_payload(h, {}, 1000, payload), ParseStatus::kOk);
  EXPECT_EQ(payload, 44u);
}

TEST(VnSpecVectors, TableSumsEqualTheTypeSizesOneByOne) {
  // fixed_types_size (four byte lookups) against Table 2.2 read one type at a time, for every
  // single type and for random sets of a group's defined types.
  std::uint32_t state = 12345u;
  const auto next = [&state] { return state = state * 1664525u + 1013904223u; };
  for (std::size_t slot = 0; slot < kGroupCount; ++slot) {
    for (int trial = 0; trial < 2000; ++trial) {
      const std::uint32_t types = trial < 32 ? (1u << trial) : next() & known_type_mask(slot);
      std::size_t expected = 0;
      for (unsigned bit = 0; bit < 32; ++bit) {
        const std::uint8_t size = type_size(slot, bit);
        if ((types >> bit) & 1u && size != kVariableSize) expected += size;
      }
      ASSERT_EQ(fixed_types_size(slot, types), expected) << "slot " << slot << " types " << types;
    }
  }
  EXPECT_EQ(variable_type_mask(kSlotGnss1), (1u << gnss_type::kSatInfo) | (1u << gnss_type::kRawMeas));
  EXPECT_EQ(variable_type_mask(kSlotImu), 0u);
}

TEST(VnSpecVectors, CorruptedExamplesAreRejectedForTheirCrc) {
  for (const char* v : {kFigA2, kFigA3, kTvD1, kTvD2, kTvD3}) {
    auto packet = from_hex(v);
    packet[packet.size() / 2] ^= 0x01;
    VnStreamDecoder d;
    test::CollectingSink sink;
    test::decode_all(d, packet, sink);
    EXPECT_EQ(d.counters().frames, 0u);
    EXPECT_GE(d.counters().bad_frames, 1u);
    EXPECT_EQ(d.counters().skipped_bytes, packet.size());
    EXPECT_TRUE(sink.measurements.empty());
  }
}

}  // namespace
}  // namespace navfuse::frontends::vectornav

// The real MIP capture from mip_sdk (../shared/captures/mip_sdk_mip_data.bin). Expected counts were
// obtained once with an independent minimal Python walker (sync 75 65, length, Fletcher checksum
// per digest §2.3, field walk LEN >= 2 within the payload), not with this code: 368940 bytes,
// 8384 packets (0x01: 1, 0x80: 7157, 0x82: 714, 0xA0: 512), 25711 fields, 0 bad, 0 skipped;
// fields (0x80,0x04) 4473, (0x80,0x05) 4473, (0x80,0x06) 3578, (0x80,0x0C) 1788, (0x82,0x05) 714.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "frontends/mip/decoder.hpp"
#include "frontends/mip/framer.hpp"
#include "tests/frontends/mip/test_util.hpp"

namespace navfuse::frontends::mip {
namespace {

std::vector<std::uint8_t> load_capture() {
  const std::filesystem::path p = std::filesystem::path(NAVFUSE_SHARED_DIR) / "captures" / "mip_sdk_mip_data.bin";
  std::ifstream in(p, std::ios::binary);
  if (!in) return {};
  return std::vector<std::uint8_t>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(MipCapture, PacketAndFieldCountsMatchTheIndependentWalk) {
  const auto bytes = load_capture();
  if (bytes.empty()) GTEST_SKIP() << "capture not present";
  ASSERT_EQ(bytes.size(), 368940u);
  Framer f;
  std::map<int, std::size_t> sets;
  std::map<int, std::size_t> fields;
  std::size_t n_fields = 0;
  f.feed(bytes, [&](const PacketView& p) {
    ++sets[p.desc_set];
    FieldWalker w(p.payload);
    FieldView fv;
    while (w.next(fv)) {
      ++n_fields;
      ++fields[p.desc_set << 8 | fv.desc];
    }
  });
  f.finish([](const PacketView&) { FAIL() << "packet found only at end of stream"; });
  EXPECT_EQ(f.counters().frames, 8384u);
  EXPECT_EQ(f.counters().bad_frames, 0u);
  EXPECT_EQ(f.counters().skipped_bytes, 0u);
  EXPECT_EQ(n_fields, 25711u);
  EXPECT_EQ(sets[0x01], 1u);
  EXPECT_EQ(sets[0x80], 7157u);
  EXPECT_EQ(sets[0x82], 714u);
  EXPECT_EQ(sets[0xA0], 512u);
  EXPECT_EQ(fields[0x8004], 4473u);
  EXPECT_EQ(fields[0x8006], 3578u);
  EXPECT_EQ(fields[0x8005], 4473u);
  EXPECT_EQ(fields[0x800C], 1788u);
  EXPECT_EQ(fields[0x8205], 714u);
}

TEST(MipCapture, DecodesToMeasurements) {
  const auto bytes = load_capture();
  if (bytes.empty()) GTEST_SKIP() << "capture not present";
  MipDecoder dec;
  test::CollectingSink sink;
  dec.feed(bytes, sink);
  dec.finish(sink);
  EXPECT_EQ(dec.counters().frames, 8384u);
  EXPECT_EQ(dec.counters().decode_errors, 0u);
  EXPECT_EQ(dec.counters().unknown_frames, 0u);
  // One IMU sample per packet with accel + gyro, one per mag field, one solution per 0x82 epoch.
  EXPECT_EQ(sink.count(MeasurementKind::kImu), 4473u);
  EXPECT_EQ(sink.count(MeasurementKind::kMagnetometer), 3578u);
  EXPECT_EQ(sink.count(MeasurementKind::kDeviceSolution), 714u);
  // No GPS timestamp in this capture: reference time (0xD5), flagged device-monotonic, increasing.
  std::int64_t prev = -1;
  std::size_t plausible = 0, imu = 0;
  for (const auto& m : sink.measurements) {
    if (kind_of(m) != MeasurementKind::kImu) continue;
    const auto& s = std::get<ImuSample>(m);
    EXPECT_EQ(s.header.time_source, TimeSource::kDeviceMonotonic);
    EXPECT_GE(s.header.time_ns, prev);
    prev = s.header.time_ns;
    ++imu;
    // A device near rest measures about 1 g of specific force.
    if (std::abs(s.accel.norm() - 9.81) < 1.0) ++plausible;
  }
  EXPECT_GT(plausible, imu * 9 / 10);
}

}  // namespace
}  // namespace navfuse::frontends::mip

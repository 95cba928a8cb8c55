// The StreamDecoder end to end: a stream written by the encoder (plus garbage and bad packets)
// decodes to exactly the frames, skipped bytes and measurements by kind that were put in it, in
// any chunking; registration with the apps (format, probe).
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/mip/decoder.hpp"
#include "frontends/mip/encoder.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/frontend.hpp"
#include "frontends/mip/writer.hpp"
#include "tests/frontends/mip/test_util.hpp"

namespace navfuse::frontends::mip {
namespace {

struct Built {
  std::vector<std::uint8_t> bytes;
  std::size_t packets = 0;
  std::size_t garbage = 0;
  std::map<MeasurementKind, std::size_t> kinds;
};

Built build_stream(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255), glen(0, 12);
  Built b;
  MipEncoder enc;
  const std::int64_t t0 = time::gps_ns_from_week_tow(2350, 100000.0);
  auto add = [&](const Measurement& m, std::size_t packets) {
    ASSERT_TRUE(enc.encode(m, b.bytes));
    b.packets += packets;
    ++b.kinds[kind_of(m)];
    if (glen(rng) > 9) {  // sometimes garbage without sync bytes
      const int n = glen(rng);
      for (int i = 0; i < n; ++i) b.bytes.push_back(static_cast<std::uint8_t>(0x00 + (byte(rng) % 0x70)));
      b.garbage += static_cast<std::size_t>(n);
    }
  };
  for (int i = 0; i < 1000; ++i) {
    MeasurementHeader h;
    h.time_ns = t0 + i * 10'000'000LL;
    h.time_source = TimeSource::kGps;
    ImuSample imu;
    imu.header = h;
    imu.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
    imu.quantity = i % 2 ? ImuQuantity::kIncrements : ImuQuantity::kRates;
    imu.gyro = {0.01, -0.02, 0.03};
    imu.accel = {0.1, 0.2, -9.8};
    add(imu, 1);
    if (i % 20 == 0) {
      GnssPosition p;
      p.header = h;
      p.header.valid = GnssPosition::kValidPosition | GnssPosition::kValidHeight;
      p.lat_rad = 0.7;
      p.lon_rad = -2.1;
      p.fix = GnssFixType::kRtkFixed;
      p.receiver_id = static_cast<std::uint8_t>((i / 20) % 2);
      add(p, 1);
      GnssVelocity v;
      v.header = h;
      v.header.valid = GnssVelocity::kValidVelocity;
      add(v, 1);
    }
    if (i % 10 == 0) {
      NavSolution s;
      s.header = h;
      s.header.valid = NavSolution::kValidPosition | NavSolution::kValidAttitude;
      s.mode = NavMode::kNavigation;
      add(s, 2);  // filter output is split into a packet and a continuation
    }
    if (i % 50 == 0) {
      GnssHeading g;
      g.header = h;
      g.header.valid = GnssHeading::kValidHeading;
      add(g, 1);
      Magnetometer m;
      m.header = h;
      m.header.valid = Magnetometer::kValidField;
      add(m, 1);
      ExternalVelocity ev;
      ev.header = h;
      ev.header.valid = ExternalVelocity::kValidX;
      ev.frame = VelocityFrame::kVehicle;
      ev.std_mps = {0.1, 0, 0};
      add(ev, 1);
    }
  }
  return b;
}

TEST(MipStream, CountersAndMeasurementsMatchWhatWasWritten) {
  const auto b = build_stream(1);
  for (int trial = 0; trial < 4; ++trial) {
    std::mt19937 rng(static_cast<std::uint32_t>(trial));
    std::uniform_int_distribution<std::size_t> cut(1, trial == 0 ? b.bytes.size() : 97);
    auto dec = frontend().make_decoder();
    ASSERT_EQ(dec->format(), "mip");
    test::CollectingSink sink;
    std::size_t pos = 0;
    while (pos < b.bytes.size()) {
      const std::size_t n = std::min(cut(rng), b.bytes.size() - pos);
      dec->feed(std::span<const std::uint8_t>(b.bytes).subspan(pos, n), sink);
      pos += n;
    }
    dec->finish(sink);
    const auto& c = dec->counters();
    EXPECT_EQ(c.bytes, b.bytes.size());
    EXPECT_EQ(c.frames, b.packets);
    EXPECT_EQ(c.bad_frames, 0u);
    EXPECT_EQ(c.skipped_bytes, b.garbage);
    EXPECT_EQ(c.unknown_frames, 0u);
    EXPECT_EQ(c.decode_errors, 0u);
    for (const auto& [kind, n] : b.kinds) EXPECT_EQ(sink.count(kind), n) << to_string(kind);
    EXPECT_EQ(sink.measurements.size(), 1000u + 50 + 50 + 100 + 20 + 20 + 20);
  }
}

TEST(MipStream, ProbeCountsValidPacketsAndRejectsOtherProtocols) {
  const auto b = build_stream(2);
  const auto head = std::span<const std::uint8_t>(b.bytes).first(4096);
  EXPECT_GT(frontend().probe(head), 20u);
  const std::string nmea = "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n";
  std::vector<std::uint8_t> text(nmea.begin(), nmea.end());
  EXPECT_EQ(frontend().probe(text), 0u);
}

TEST(MipStream, CorruptedStreamNeverCrashesAndAccountsForEveryByte) {
  auto b = build_stream(3);
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> byte(0, 255);
  for (auto& x : b.bytes)
    if (byte(rng) < 3) x = static_cast<std::uint8_t>(byte(rng));
  MipDecoder dec;
  test::CollectingSink sink;
  sink.frames = true;  // exercise FrameRecord building on corrupted input too
  dec.feed(b.bytes, sink);
  dec.finish(sink);
  const auto& c = dec.counters();
  EXPECT_GT(c.bad_frames, 0u);
  EXPECT_LT(c.frames, b.packets);
  EXPECT_EQ(sink.records.size(), c.frames);
  Framer f;
  std::size_t framed = 0;
  f.feed(b.bytes, [&](const PacketView& p) { framed += p.bytes.size(); });
  f.finish([&](const PacketView& p) { framed += p.bytes.size(); });
  EXPECT_EQ(framed + f.counters().skipped_bytes, b.bytes.size());
  EXPECT_EQ(f.counters().skipped_bytes, c.skipped_bytes);
}

TEST(MipStream, ReferenceTimeIsMappedToGpsOnceBothAreSeen) {
  // 0x80 packets with D3 + D5 teach the clock model; a later packet with D5 only gets GPS time.
  std::vector<std::uint8_t> bytes;
  const std::int64_t gps0 = time::gps_ns_from_week_tow(2350, 5000.0);
  const std::int64_t ref0 = 42'000'000'000;
  for (int i = 0; i < 5; ++i) {
    PacketWriter w(bytes, 0x80);
    const auto wt = time::week_tow_from_gps_ns(gps0 + i * 10'000'000LL);
    auto& d3 = w.field(0xD3);
    d3.f64(wt.tow_s);
    d3.u16(static_cast<std::uint16_t>(wt.week));
    d3.u16(3);
    w.field(0xD5).u64(static_cast<std::uint64_t>(ref0 + i * 10'000'000LL));
    auto& a = w.field(0x04);
    a.f32(0);
    a.f32(0);
    a.f32(-1);
    w.finish();
  }
  {
    PacketWriter w(bytes, 0x80);
    w.field(0xD5).u64(static_cast<std::uint64_t>(ref0 + 100'000'000LL));
    auto& a = w.field(0x04);
    a.f32(0);
    a.f32(0);
    a.f32(-1);
    w.finish();
  }
  MipDecoder dec;
  test::CollectingSink sink;
  dec.feed(bytes, sink);
  dec.finish(sink);
  ASSERT_EQ(sink.measurements.size(), 6u);
  const auto& last = header_of(sink.measurements.back());
  EXPECT_EQ(last.time_source, TimeSource::kGps);
  EXPECT_NEAR(static_cast<double>(last.time_ns - gps0), 100e6, 1e3);
  EXPECT_NEAR(std::get<ImuSample>(sink.measurements[0]).accel.z(), -9.80665, 1e-6);  // 1 g
}

}  // namespace
}  // namespace navfuse::frontends::mip

// UnicoreDecoder on a stream built from the spec's examples plus damage: counters, measurements
// by kind and value, the date policy, chunked feeding and frame records.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/unicore/decoder.hpp"
#include "frontends/unicore/frontend.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::unicore {
namespace {

using test::CollectingSink;

std::string with_checksum(const std::string& body) {
  char hex[3];
  std::snprintf(hex, sizeof hex, "%02X", bytes::nmea_xor(body));
  return "$" + body + "*" + hex + "\r\n";
}

struct ExampleStream {
  std::string bytes;
  std::size_t valid = 0;  // sentences that pass the framer
  std::size_t skipped = 0;
};

ExampleStream example_stream() {
  ExampleStream s;
  const auto add = [&](const std::string& sentence, bool valid = true) {
    s.bytes += sentence;
    if (valid) ++s.valid; else s.skipped += sentence.size();
  };
  // NAVATT before any date: dropped for lack of a date (the documented policy).
  add("$NAVATT,060917.00,7,-168753,114146,159559,15459,16206,19998*17\r\n");
  add("$GYOACC,081118,053152.000,0.017618,0.031686,0.019729,200,6.489322,-6.913150,2.960812,200,0,5,200,1*2C\r\n");
  add("$GYOACC-V,081118,053152.000,0.017618,0.031686,0.019729,200,6.489322,-6.913150,2.960812,200,0,5,200,1*57\r\n");
  add(with_checksum("GYOACC-V,081118,053152.200,,,,200,,,,200,0,5,200,0"));  // not aligned yet
  add("$NAVPOS,282201000,5,3,-2160481.168,4383619.182,4084735.203,40.078998,116.236534,52.843847*1C\r\n");
  add("$NAVVEL,282201000,5,3,0.000,0.000,0.000,31.785*2F\r\n");
  const std::string garbage = "\x01\x02garbage\xff";
  s.bytes += garbage;
  s.skipped += garbage.size();
  add("$GPGGA,060845.00,4004.74005,N,11614.19613,E,1,10,0.85,53.5,M,,M,,*7B\r\n");
  add("$NAVACC,085206.00,A,2480,70,1250*7D\r\n", false);  // printed checksum is wrong (L1353)
  add("$FOOBAR,1,2\r\n");                                // unknown name
  add("$SNRSTAT,3,0,x,2\r\n");                            // known name, bad field
  add("$NOTICE,1,10000,10000,10000,20,0,FFFF,FFFF,FFFF,1000*29\r\n");
  add("$SNRSTAT,3,0,0,2*5C\r\n");
  add("$GPGSV,3,01,11,02,34,277,41,03,16,043,35,05,04,215,35,06,69,333,48,0*57\r\n");
  add("$BDGSV,2,2,5,168,5,,50*52\r\n");
  add("$OK*04\r\n");
  add("#CFGPRT,1,h0,115200,3,35\r\n");
  return s;
}

TEST(UnicoreDecoder, ExampleStreamCountersAndKinds) {
  const ExampleStream s = example_stream();
  UnicoreDecoder d;
  CollectingSink sink;
  d.feed(bytes::as_bytes(s.bytes), sink);
  d.finish(sink);
  const auto& c = d.counters();
  EXPECT_EQ(c.bytes, s.bytes.size());
  EXPECT_EQ(c.frames, s.valid);
  EXPECT_EQ(c.bad_frames, 1u);
  EXPECT_EQ(c.skipped_bytes, s.skipped);
  EXPECT_EQ(c.unknown_frames, 1u);
  EXPECT_EQ(c.decode_errors, 1u);
  EXPECT_EQ(sink.count(MeasurementKind::kImu), 2u);
  EXPECT_EQ(sink.count(MeasurementKind::kWheelTicks), 1u);
  EXPECT_EQ(sink.count(MeasurementKind::kVehicleSpeed), 0u);  // no scale configured
  EXPECT_EQ(sink.count(MeasurementKind::kGnssPosition), 1u);
  EXPECT_EQ(sink.count(MeasurementKind::kGnssVelocity), 1u);
  EXPECT_EQ(sink.count(MeasurementKind::kDeviceSolution), 1u);
  EXPECT_EQ(sink.measurements.size(), 6u);
  EXPECT_EQ(d.drops().no_date, 1u);
  EXPECT_EQ(d.drops().imu_not_aligned, 1u);
}

TEST(UnicoreDecoder, ExampleStreamValues) {
  const ExampleStream s = example_stream();
  DecoderOptions opt;
  opt.odometer_m_per_pulse = 0.02;
  UnicoreDecoder d(opt);
  CollectingSink sink;
  d.feed(bytes::as_bytes(s.bytes), sink);
  const std::int64_t t_imu = *time::gps_ns_from_utc({2018, 11, 8, 5, 31, 52.0});
  const auto& imu = std::get<ImuSample>(sink.measurements[0]);
  EXPECT_EQ(imu.header.time_ns, t_imu);
  EXPECT_EQ(imu.header.time_source, TimeSource::kGps);
  EXPECT_TRUE(imu.low_rate);
  EXPECT_EQ(imu.frame, SensorFrame::kSensor);
  EXPECT_DOUBLE_EQ(imu.dt_s, 0.2);
  EXPECT_DOUBLE_EQ(imu.gyro.x(), 0.017618);
  EXPECT_DOUBLE_EQ(imu.accel.y(), -6.913150);
  const auto& ticks = std::get<WheelTicks>(sink.measurements[1]);
  EXPECT_EQ(ticks.channels, 1);
  EXPECT_EQ(ticks.ticks[0], 5u);
  EXPECT_DOUBLE_EQ(ticks.period_s, 0.2);
  EXPECT_EQ(ticks.gear, Gear::kReverse);  // fwd = 1 means reverse (L755)
  // 5 pulses of 2 cm in 0.2 s, reversing.
  const auto& speed = std::get<VehicleSpeed>(sink.measurements[2]);
  EXPECT_DOUBLE_EQ(speed.speed_mps, -0.5);
  // GYOACC-V: right-forward-up (L797-L800) -> forward-right-down.
  const auto& imu_v = std::get<ImuSample>(sink.measurements[3]);
  EXPECT_EQ(imu_v.frame, SensorFrame::kVehicle);
  EXPECT_DOUBLE_EQ(imu_v.gyro.x(), 0.031686);
  EXPECT_DOUBLE_EQ(imu_v.gyro.y(), 0.017618);
  EXPECT_DOUBLE_EQ(imu_v.gyro.z(), -0.019729);
  EXPECT_DOUBLE_EQ(imu_v.accel.x(), -6.913150);
  // NAVPOS: ms of week in the week of the anchor (Thursday 2018-11-08) -> Wednesday 06:23:21.
  const auto& pos = std::get<GnssPosition>(sink.measurements[4]);
  const std::int32_t week = time::week_tow_from_gps_ns(t_imu).week;
  EXPECT_EQ(pos.header.time_ns, time::gps_ns_from_week_tow(week, 282201.0));
  EXPECT_NEAR(pos.lat_rad * rot::kRadToDeg, 40.078998, 1e-12);
  EXPECT_DOUBLE_EQ(pos.height_m, 52.843847);
  EXPECT_EQ(pos.fix, GnssFixType::kFix3D);
  EXPECT_FALSE(pos.header.valid & GnssPosition::kValidCovariance);  // no NAVACC yet
  const auto& vel = std::get<GnssVelocity>(sink.measurements[5]);
  EXPECT_EQ(vel.header.time_ns, pos.header.time_ns);
  EXPECT_NEAR(vel.vel_ned_mps.norm(), 0.0, 1e-12);
  // GGA: time of day 06:08:45 UTC on the day of the last anchor (2018-11-07).
  const auto& sol = std::get<NavSolution>(sink.measurements[6]);
  EXPECT_EQ(sol.header.time_ns, *time::gps_ns_from_utc({2018, 11, 7, 6, 8, 45.0}));
  EXPECT_EQ(sol.mode, NavMode::kNavigation);
  EXPECT_NEAR(sol.lat_rad * rot::kRadToDeg, 40.0 + 4.74005 / 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(sol.height_m, 53.5);  // ellipsoidal with CFGGEOID 0 (L885-L887)
  EXPECT_TRUE(sol.header.valid & NavSolution::kValidPosition);
  EXPECT_FALSE(sol.header.valid & NavSolution::kValidUndulation);
}

TEST(UnicoreDecoder, ChunkedFeedingGivesTheSameResult) {
  std::string stream;
  for (int i = 0; i < 20; ++i) stream += example_stream().bytes;
  UnicoreDecoder whole;
  CollectingSink expected;
  whole.feed(bytes::as_bytes(stream), expected);
  whole.finish(expected);
  std::mt19937 rng(61);
  for (int trial = 0; trial < 20; ++trial) {
    UnicoreDecoder d;
    CollectingSink sink;
    std::size_t at = 0;
    while (at < stream.size()) {
      const std::size_t n = std::min<std::size_t>(stream.size() - at, rng() % 300);
      d.feed(bytes::as_bytes(std::string_view(stream).substr(at, n)), sink);
      at += n;
    }
    d.finish(sink);
    ASSERT_EQ(sink.measurements.size(), expected.measurements.size());
    for (std::size_t i = 0; i < sink.measurements.size(); ++i) {
      EXPECT_EQ(kind_of(sink.measurements[i]), kind_of(expected.measurements[i]));
      EXPECT_EQ(header_of(sink.measurements[i]).time_ns, header_of(expected.measurements[i]).time_ns);
    }
    EXPECT_EQ(d.counters().frames, whole.counters().frames);
    EXPECT_EQ(d.counters().bad_frames, whole.counters().bad_frames);
    EXPECT_EQ(d.counters().skipped_bytes, whole.counters().skipped_bytes);
    EXPECT_EQ(d.counters().decode_errors, whole.counters().decode_errors);
  }
}

TEST(UnicoreDecoder, FrameRecordsCarryNamesAndFields) {
  UnicoreDecoder d;
  CollectingSink sink(true);
  const std::string s = example_stream().bytes;
  d.feed(bytes::as_bytes(s), sink);
  ASSERT_FALSE(sink.records.empty());
  const auto find = [&](std::string_view name) -> const frontends::FrameRecord* {
    for (const auto& r : sink.records) {
      if (r.name == name) return &r;
    }
    return nullptr;
  };
  const auto* gga = find("GPGGA");
  ASSERT_NE(gga, nullptr);
  EXPECT_EQ(gga->protocol, "unicore");
  EXPECT_EQ(gga->offset, s.find("$GPGGA"));
  const auto lat = std::find_if(gga->fields.begin(), gga->fields.end(), [](const auto& f) { return f.first == "lat_deg"; });
  ASSERT_NE(lat, gga->fields.end());
  EXPECT_NEAR(std::get<double>(lat->second), 40.0 + 4.74005 / 60.0, 1e-12);
  EXPECT_NE(find("GYOACC-V"), nullptr);
  EXPECT_NE(find("NOTICE"), nullptr);
  EXPECT_NE(find("$OK"), nullptr);
  EXPECT_NE(find("#CFGPRT"), nullptr);
  EXPECT_EQ(find("FOOBAR"), nullptr);  // unknown frames are counted, not recorded
  const auto* att = find("NAVATT");
  ASSERT_NE(att, nullptr);
  EXPECT_NEAR(std::get<double>(att->fields[2].second), -1.68753, 1e-12);  // roll_deg
}

TEST(UnicoreDecoder, CaseInsensitiveNamesAndMissingChecksum) {
  UnicoreDecoder d;
  CollectingSink sink;
  const std::string s =
      "$gyoacc,081118,053152.000,0.017618,0.031686,0.019729,200,6.489322,-6.913150,2.960812,200,0,5,200,0\r\n";
  d.feed(bytes::as_bytes(s), sink);
  EXPECT_EQ(d.counters().frames, 1u);
  EXPECT_EQ(sink.count(MeasurementKind::kImu), 1u);
}

TEST(UnicoreDecoder, RandomCorruptionNeverBreaksTheCounters) {
  std::string clean;
  for (int i = 0; i < 50; ++i) clean += example_stream().bytes;
  std::mt19937 rng(7);
  for (int trial = 0; trial < 30; ++trial) {
    std::string s = clean;
    for (std::size_t k = 0; k < s.size() / 50; ++k) s[rng() % s.size()] = static_cast<char>(rng());
    s.insert(rng() % s.size(), std::string(300, 'A'));  // an over-long line
    UnicoreDecoder d;
    CollectingSink sink;
    d.feed(bytes::as_bytes(s), sink);
    d.finish(sink);
    const auto& c = d.counters();
    EXPECT_EQ(c.bytes, s.size());
    EXPECT_LE(c.skipped_bytes, c.bytes);
    EXPECT_LE(c.unknown_frames + c.decode_errors, c.frames);
    EXPECT_LT(c.frames, clean.size());
    for (const auto& m : sink.measurements) EXPECT_EQ(header_of(m).time_source, TimeSource::kGps);
  }
}

TEST(UnicoreFrontend, ProbeCountsOnlyThisProtocol) {
  const auto& fe = frontends::unicore::frontend();
  EXPECT_EQ(fe.format, "unicore");
  const std::string s = example_stream().bytes;
  // Checksummed sentences with known names: NAVATT, GYOACC, GYOACC-V x2, NAVPOS, NAVVEL, GPGGA,
  // NOTICE, SNRSTAT, GPGSV, BDGSV (the $OK reply and unchecksummed lines do not count).
  EXPECT_EQ(fe.probe(bytes::as_bytes(s)), 11u);
  EXPECT_EQ(fe.probe(bytes::as_bytes(std::string("$VNYMR,+006.380,+000.023*65\r\nhello\r\n"))), 0u);
  EXPECT_EQ(fe.make_decoder()->format(), "unicore");
  EXPECT_NE(fe.make_encoder(), nullptr);
}

}  // namespace
}  // namespace navfuse::frontends::unicore

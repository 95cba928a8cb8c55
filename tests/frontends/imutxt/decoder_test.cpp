// The KF-GINS-style IMU text reader on small files written here: values, times in the given GPS
// week (hand-computed), dt from consecutive times, comments and damaged lines counted, the
// Sunday rollover, and detection that neither steals nor is stolen by RTKLIB/NMEA text.
#include <gtest/gtest.h>

#include "frontends/imutxt/decoder.hpp"
#include "frontends/imutxt/frontend.hpp"
#include "frontends/rtklib/frontend.hpp"
#include "text_decode.hpp"

namespace navfuse::frontends::imutxt {
namespace {

using test::decode_text;

// Week 2381 starts 2381 * 604800 s = 1,440,028,800 s after the GPS epoch.
constexpr std::int64_t kWeek2381Ns = 1'440'028'800LL * 1'000'000'000LL;

constexpr std::string_view kFile =
    "# KF-GINS imu file\n"
    "time gx gy gz ax ay az\n"
    "100.000 0.001 0.002 0.003 0.01 0.02 9.81e-2 17.5\n"  // an extra column (temperature)
    "100.005, 0.004, 0.005, 0.006, 0.04, 0.05, 0.06\r\n"  // comma separated, CRLF
    "\n"
    "100.010 nan 0 0 0 0 0\n"         // NaN
    "100.015 0.1 0.2\n"               // too few columns
    "100.020 abc 0 0 0 0 0\n"         // not a number
    "100.025 1e-3 0 0 0 0 -2e-3";     // no newline at the end

TEST(ImuText, DecodesSamplesCountsCommentsAndDamage) {
  ImuTextDecoder decoder(2381);
  const auto sink = decode_text(decoder, kFile);
  const auto imu = sink.all<ImuSample>();
  ASSERT_EQ(imu.size(), 3u);
  EXPECT_EQ(imu[0].header.time_ns, kWeek2381Ns + 100'000'000'000LL);
  EXPECT_EQ(imu[0].header.time_source, TimeSource::kGps);
  EXPECT_EQ(imu[0].quantity, ImuQuantity::kIncrements);
  EXPECT_EQ(imu[0].frame, SensorFrame::kSensor);
  EXPECT_EQ(imu[0].gyro, Eigen::Vector3d(0.001, 0.002, 0.003));
  EXPECT_EQ(imu[0].accel, Eigen::Vector3d(0.01, 0.02, 0.0981));
  EXPECT_EQ(imu[0].dt_s, 0.0);  // first sample: interval unknown
  EXPECT_EQ(imu[1].header.time_ns, kWeek2381Ns + 100'005'000'000LL);
  EXPECT_NEAR(imu[1].dt_s, 0.005, 1e-9);
  EXPECT_EQ(imu[1].accel, Eigen::Vector3d(0.04, 0.05, 0.06));
  // After damaged lines the next sample's interval is unknown (its predecessor was lost): dt 0.
  EXPECT_EQ(imu[2].header.time_ns, kWeek2381Ns + 100'025'000'000LL);
  EXPECT_EQ(imu[2].dt_s, 0.0);
  EXPECT_EQ(imu[2].accel.z(), -2e-3);
  const StreamCounters& c = decoder.counters();
  EXPECT_EQ(c.frames, 3u);
  EXPECT_EQ(c.unknown_frames, 2u);  // comment and column header
  EXPECT_EQ(c.bad_frames, 3u);
  EXPECT_EQ(c.bytes, kFile.size());
  ASSERT_EQ(sink.records.size(), 3u);
  EXPECT_EQ(sink.records[1].offset, kFile.find("100.005"));
}

TEST(ImuText, ChunkingDoesNotChangeTheResult) {
  ImuTextDecoder whole(2381);
  const auto a = decode_text(whole, kFile);
  for (std::size_t chunk : {1u, 3u, 17u}) {
    ImuTextDecoder chunked(2381);
    const auto b = decode_text(chunked, kFile, chunk);
    EXPECT_EQ(b.measurements.size(), a.measurements.size());
    EXPECT_EQ(chunked.counters().frames, whole.counters().frames);
    EXPECT_EQ(chunked.counters().bad_frames, whole.counters().bad_frames);
    EXPECT_EQ(chunked.counters().skipped_bytes, whole.counters().skipped_bytes);
  }
}

TEST(ImuText, SundayRolloverContinuesInTheNextWeek) {
  ImuTextDecoder decoder(2381);
  const auto imu = decode_text(decoder, "604799.995 0 0 0 0 0 0\n0.005 0 0 0 0 0 0\n").all<ImuSample>();
  ASSERT_EQ(imu.size(), 2u);
  EXPECT_EQ(imu[1].header.time_ns, kWeek2381Ns + 604'800'005'000'000LL);
  EXPECT_NEAR(imu[1].dt_s, 0.010, 1e-9);
}

TEST(ImuText, WithoutAWeekTimesAreBareSecondsOfWeek) {
  ImuTextDecoder decoder;
  const auto imu = decode_text(decoder, "12.5 0 0 0 0 0 0\n").all<ImuSample>();
  ASSERT_EQ(imu.size(), 1u);
  EXPECT_EQ(imu[0].header.time_ns, 12'500'000'000LL);
  EXPECT_EQ(imu[0].header.time_source, TimeSource::kUnknown);
}

TEST(ImuText, BinaryAndOverlongLinesAreBadFramesNotCrashes) {
  ImuTextDecoder decoder(2381);
  std::string text = "1.0 0 0 0 0 0 0\n";
  text += std::string("\x01\x02\x00\xff", 4) + "\n";
  text += std::string(5000, '1') + "\n";
  text += "1.01 0 0 0 0 0 0\n";
  const auto sink = decode_text(decoder, text);
  EXPECT_EQ(sink.measurements.size(), 2u);
  EXPECT_EQ(decoder.counters().bad_frames, 2u);
}

TEST(ImuText, DetectionTellsImuTextFromRtklibAndNmea) {
  const auto& imu = imutxt::frontend();
  const auto& rtk = rtklib::frontend();
  const std::string imu_text = "100.000 1e-5 2e-5 3e-5 1e-3 2e-3 5.9e-2\n100.006 1e-5 2e-5 3e-5 1e-3 2e-3 5.9e-2\n";
  EXPECT_EQ(imu.probe(test::bytes_of(imu_text)), 2u);
  EXPECT_EQ(rtk.probe(test::bytes_of(imu_text)), 0u);
  // An RTKLIB week/seconds line is all numbers too, but its "angle increments" are a latitude.
  const std::string pos = "2381 408639.749 40.0966916 -105.1471665 1601.435 1 25 0.01 0.01 0.01 0 0 0 0 0\n";
  EXPECT_EQ(imu.probe(test::bytes_of(pos)), 0u);
  EXPECT_EQ(rtk.probe(test::bytes_of(pos)), 1u);
  const std::string nmea = "$GPGGA,172814.0,3723.46587704,N,12202.26957864,W,2,6,1.2,18.893,M,-25.669,M,2.0,0031*4F\n";
  EXPECT_EQ(imu.probe(test::bytes_of(nmea)), 0u);
  EXPECT_EQ(rtk.probe(test::bytes_of(nmea)), 0u);
}

}  // namespace
}  // namespace navfuse::frontends::imutxt

// Truth CSV reading and interpolation, error statistics and the time-base gate, against hand
// computation.
#include <cmath>

#include <gtest/gtest.h>

#include "apps/common/command_error.hpp"
#include "apps/replay/error_stats.hpp"
#include "apps/fusion/time_base_gate.hpp"
#include "apps/replay/truth_accuracy.hpp"
#include "apps/replay/truth_track.hpp"
#include "core/rotation/rotation.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

using testing::scratch_dir;
using testing::write_text;

constexpr const char* kHeader =
    "time_gps_s,lat_deg,lon_deg,height_m,vn,ve,vd,roll_deg,pitch_deg,yaw_deg,stationary,gnss_available\n";

TEST(ParseTimeNs, ExactNanoseconds) {
  EXPECT_EQ(parse_time_ns("1234.000000001"), 1'234'000'000'001LL);
  EXPECT_EQ(parse_time_ns("5"), 5'000'000'000LL);
  EXPECT_EQ(parse_time_ns("5.5"), 5'500'000'000LL);
  EXPECT_FALSE(parse_time_ns("5.1234567891"));
  EXPECT_FALSE(parse_time_ns("x"));
}

TEST(TruthTrack, InterpolatesLinearlyAndAcrossTheYawWrap) {
  const auto dir = scratch_dir();
  write_text(dir / "t.csv", std::string(kHeader) +
                                "100.000000000,10.0,20.0,50.0,1.0,0.0,0.0,0.0,0.0,179.0,0,1\n"
                                "100.010000000,10.0001,20.0002,52.0,3.0,2.0,0.0,2.0,0.0,-179.0,0,0\n");
  TruthTrack t((dir / "t.csv").string());
  const auto p = t.at(100'002'500'000LL);  // a quarter of the way
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->lat_rad * rot::kRadToDeg, 10.000025, 1e-9);
  EXPECT_NEAR(p->lon_rad * rot::kRadToDeg, 20.00005, 1e-9);
  EXPECT_NEAR(p->height_m, 50.5, 1e-9);
  EXPECT_NEAR(p->vel_ned_mps.x(), 1.5, 1e-12);
  EXPECT_NEAR(p->vel_ned_mps.y(), 0.5, 1e-12);
  EXPECT_NEAR(p->rpy_rad.x() * rot::kRadToDeg, 0.5, 1e-9);
  // 179 -> -179 is +2 deg through 180: a quarter is 179.5, not 89.5.
  EXPECT_NEAR(p->rpy_rad.z() * rot::kRadToDeg, 179.5, 1e-9);
  EXPECT_FALSE(p->gnss_available);  // the interval touches an outage row
  const auto end = t.at(100'010'000'000LL);
  ASSERT_TRUE(end);
  EXPECT_NEAR(end->height_m, 52.0, 1e-12);
  EXPECT_FALSE(t.at(100'020'000'000LL));  // past the end
}

TEST(TruthTrack, BeforeTheFirstRowThereIsNoTruth) {
  const auto dir = scratch_dir();
  write_text(dir / "t.csv", std::string(kHeader) + "100.0,10,20,50,0,0,0,0,0,0,1,1\n100.005,10,20,50,0,0,0,0,0,0,1,1\n");
  TruthTrack t((dir / "t.csv").string());
  EXPECT_FALSE(t.at(99'000'000'000LL));
  EXPECT_TRUE(t.at(100'000'000'000LL));
}

TEST(TruthTrack, NotATruthFileIsAnErrorNamingTheColumn) {
  const auto dir = scratch_dir();
  write_text(dir / "t.csv", "a,b,c\n1,2,3\n");
  try {
    TruthTrack t((dir / "t.csv").string());
    FAIL();
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("time_gps_s"), std::string::npos);
  }
}

TEST(ErrorStats, NearestRankPercentilesAndRms) {
  ErrorStats s;
  for (int i = 1; i <= 100; ++i) s.add(static_cast<double>(101 - i));  // 100 .. 1, unsorted
  const ErrorSummary e = s.summary();
  EXPECT_EQ(e.samples, 100u);
  EXPECT_DOUBLE_EQ(e.p50, 50.0);
  EXPECT_DOUBLE_EQ(e.p95, 95.0);
  EXPECT_DOUBLE_EQ(e.p99, 99.0);
  EXPECT_DOUBLE_EQ(e.max, 100.0);
  // sum of k^2 for k = 1..100 is 100*101*201/6 = 338350.
  EXPECT_NEAR(e.rms, std::sqrt(338350.0 / 100.0), 1e-12);
}

TEST(TruthAccuracy, ErrorsOfAKnownOffset) {
  const auto dir = scratch_dir();
  write_text(dir / "t.csv", std::string(kHeader) + "100.0,45.0,7.0,10.0,1,2,0,1,2,30,0,1\n"
                                                   "100.1,45.0,7.0,10.0,1,2,0,1,2,30,0,1\n");
  TruthAccuracy acc((dir / "t.csv").string());
  NavSolution s;
  s.mode = NavMode::kNavigation;
  s.header.time_ns = 100'050'000'000LL;
  // 3 m north, 4 m east of the truth: 5 m horizontal (meridian radius M and prime vertical N of
  // WGS-84 at 45 deg from core geodesy; small-angle offsets are exact to < 1 mm here).
  const double lat = 45.0 * rot::kDegToRad;
  const double a = 6378137.0, e2 = 6.69437999014e-3;
  const double w = std::sqrt(1.0 - e2 * std::sin(lat) * std::sin(lat));
  const double m_radius = a * (1.0 - e2) / (w * w * w), n_radius = a / w;
  s.lat_rad = lat + 3.0 / (m_radius + 10.0);
  s.lon_rad = 7.0 * rot::kDegToRad + 4.0 / ((n_radius + 10.0) * std::cos(lat));
  s.height_m = 8.0;
  s.vel_ned_mps = {1.0, 2.0, 0.3};
  s.rpy_rad = Eigen::Vector3d(1.5, 2.0, 30.0 - 359.0) * rot::kDegToRad;  // yaw differs by 1 deg mod 360
  acc.add(s);
  s.mode = NavMode::kAhrs;  // not a navigation solution: not compared
  acc.add(s);
  ASSERT_EQ(acc.samples(), 1u);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kHorizontal).max, 5.0, 1e-3);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kVertical).max, 2.0, 1e-9);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kVelocity).max, 0.3, 1e-9);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kRoll).max, 0.5, 1e-9);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kPitch).max, 0.0, 1e-9);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kHeading).max, 1.0, 1e-9);
  const auto j = acc.to_json();
  EXPECT_EQ(j["samples"], 1);
  EXPECT_EQ(j["gnss_outage"]["samples"], 0);
  EXPECT_TRUE(j["horizontal_m"].contains("p95"));
}

Measurement with_header(Measurement m, std::int64_t t, TimeSource src, std::uint16_t stream) {
  auto& h = header_of(m);
  h.time_ns = t;
  h.time_source = src;
  h.stream_id = stream;
  return m;
}

TEST(TimeBaseGate, GpsFromAnyStreamDeviceClockOnlyFromTheImuStream) {
  TimeBaseGate gate;
  EXPECT_FALSE(gate.check(with_header(ImuSample{}, 1, TimeSource::kGps, 0)));
  EXPECT_FALSE(gate.check(with_header(VehicleSpeed{}, 2, TimeSource::kGps, 1)));
  EXPECT_EQ(gate.check(with_header(VehicleSpeed{}, 2, TimeSource::kDeviceMonotonic, 1)), "time_base");
  EXPECT_EQ(gate.check(with_header(VehicleSpeed{}, 2, TimeSource::kHostArrival, 0)), "time_base");
  EXPECT_EQ(gate.check(with_header(ImuSample{}, 3, TimeSource::kGps, 1)), "second_imu");
  // Device solutions are not fused: never gated.
  EXPECT_FALSE(gate.check(with_header(NavSolution{}, 2, TimeSource::kDeviceMonotonic, 1)));
  // An IMU on its own device clock: only that device's measurements share it.
  TimeBaseGate mono;
  EXPECT_FALSE(mono.check(with_header(ImuSample{}, 1, TimeSource::kDeviceMonotonic, 0)));
  EXPECT_FALSE(mono.check(with_header(GnssPosition{}, 1, TimeSource::kDeviceMonotonic, 0)));
  EXPECT_EQ(mono.check(with_header(GnssPosition{}, 1, TimeSource::kDeviceMonotonic, 1)), "time_base");
  EXPECT_EQ(mono.check(with_header(GnssPosition{}, 1, TimeSource::kGps, 0)), "time_base");
}

}  // namespace
}  // namespace navfuse::apps

namespace navfuse::apps {
namespace {

// --gnss-outage scoring: windows from the first IMU sample; the last comparison inside each
// window is that outage's end error. Truth stands still; the solution drifts north 1 m per s.
TEST(TruthAccuracy, EndOfOutageErrorIsTheLastErrorInEachWindow) {
  const auto dir = testing::scratch_dir();
  std::string csv = "time_gps_s,lat_deg,lon_deg,height_m,vn,ve,vd,roll_deg,pitch_deg,yaw_deg,stationary,gnss_available\n";
  for (int i = 0; i <= 40; ++i) csv += std::to_string(100 + i) + ".0,45.0,7.0,10.0,0,0,0,0,0,0,0,1\n";
  testing::write_text(dir / "t.csv", csv);
  TruthAccuracy acc((dir / "t.csv").string());
  std::string error;
  const auto plan = GnssOutagePlan::parse("10:4", error);  // outages 0-4, 10-14, 20-24, 30-34 s
  ASSERT_TRUE(plan);
  acc.use_outage_plan(*plan, 100'000'000'000LL);
  const double lat = 45.0 * rot::kDegToRad;
  const double a = 6378137.0, e2 = 6.69437999014e-3;
  const double w = std::sqrt(1.0 - e2 * std::sin(lat) * std::sin(lat));
  const double m_radius = a * (1.0 - e2) / (w * w * w);
  for (int i = 0; i < 40; ++i) {  // one pose per second, i metres north at 100 + i s
    NavSolution s;
    s.mode = NavMode::kNavigation;
    s.header.time_ns = (100 + i) * 1'000'000'000LL;
    s.lat_rad = lat + i / (m_radius + 10.0);
    s.lon_rad = 7.0 * rot::kDegToRad;
    s.height_m = 10.0;
    acc.add(s);
  }
  const auto j = acc.to_json()["gnss_outage"]["end_of_outage_horizontal_m"];
  ASSERT_EQ(j["outages"], 4);
  // Last pose in each window: 3, 13, 23, 33 s -> 3, 13, 23, 33 m; mean 18 m.
  EXPECT_NEAR(j["each"][1]["horizontal_m"].get<double>(), 13.0, 1e-3);
  EXPECT_NEAR(j["mean"].get<double>(), 18.0, 1e-3);
  EXPECT_NEAR(j["max"].get<double>(), 33.0, 1e-3);
  EXPECT_EQ(acc.to_json()["gnss_outage"]["samples"], 16);  // 4 poses in each of 4 windows
}

}  // namespace
}  // namespace navfuse::apps

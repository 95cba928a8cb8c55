// decode(encode(m)) reproduces m to the protocol's resolution, for every measurement kind the
// VN-300 carries, with random values (fixed seed).
#include <gtest/gtest.h>

#include <random>

#include "core/rotation/rotation.hpp"
#include "frontends/vectornav/encoder.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::vectornav {
namespace {

constexpr double kFloatRel = 2e-7;  // IEEE binary32: 2^-23 relative
constexpr std::int64_t kT0 = 2303LL * 604800 * 1'000'000'000LL + 501342'000'000'000LL;

struct Harness {
  VnMeasurementEncoder encoder;
  VnStreamDecoder decoder;
  test::CollectingSink sink{true};
  std::vector<std::uint8_t> bytes;
  // Encodes and decodes one measurement; returns what came out.
  std::vector<Measurement> round_trip(const Measurement& m) {
    bytes.clear();
    EXPECT_TRUE(encoder.encode(m, bytes));
    sink.measurements.clear();
    decoder.feed(bytes, sink);
    return sink.measurements;
  }
};

double uni(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
Eigen::Vector3d vec(std::mt19937_64& rng, double lo, double hi) { return {uni(rng, lo, hi), uni(rng, lo, hi), uni(rng, lo, hi)}; }

void expect_near_rel(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double scale) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], scale * kFloatRel * 4 + 1e-12) << i;
}

TEST(VnMeasurementRoundTrip, ImuRatesAndIncrements) {
  std::mt19937_64 rng(11);
  Harness h;
  for (int i = 0; i < 500; ++i) {
    ImuSample s;
    s.header = {kT0 + i * 5'000'000LL, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
    s.quantity = (i % 2) ? ImuQuantity::kIncrements : ImuQuantity::kRates;
    s.gyro = vec(rng, -5, 5);
    s.accel = vec(rng, -50, 50);
    s.dt_s = s.quantity == ImuQuantity::kIncrements ? 0.005 : 0.0;
    s.saturation = static_cast<std::uint8_t>(rng() & 0x3F);
    if (i % 7 == 3) s.header.valid &= ~ImuSample::kValidAccel;  // a failed accelerometer
    const auto out = h.round_trip(s);
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<ImuSample>(out[0]);
    EXPECT_EQ(d.header.time_ns, s.header.time_ns);
    EXPECT_EQ(d.header.time_source, TimeSource::kGps);
    EXPECT_EQ(d.header.valid, s.header.valid);
    EXPECT_EQ(d.quantity, s.quantity);
    EXPECT_EQ(d.saturation, s.saturation);
    expect_near_rel(d.gyro, s.gyro, 5);
    expect_near_rel(d.accel, s.accel, 50);
    if (s.quantity == ImuQuantity::kIncrements) {
      EXPECT_NEAR(d.dt_s, 0.005, 1e-9);
      // DeltaTheta/DeltaVel are coning- and sculling-integrated on board (ICD 2.4.7-2.4.8).
      EXPECT_EQ(d.increments, ImuIncrements::kCompensated);
    } else if (i > 1) {
      EXPECT_NEAR(d.dt_s, 0.010, 1e-9);  // spacing of consecutive rate samples
    }
  }
}

TEST(VnMeasurementRoundTrip, MonotonicTimeBeforeGps) {
  Harness h;
  ImuSample s;
  s.header = {123'456'789'000LL, TimeSource::kDeviceMonotonic, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
  const auto out = h.round_trip(s);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(header_of(out[0]).time_source, TimeSource::kDeviceMonotonic);
  EXPECT_EQ(header_of(out[0]).time_ns, s.header.time_ns);
}

TEST(VnMeasurementRoundTrip, DeviceSolution) {
  std::mt19937_64 rng(12);
  Harness h;
  for (int i = 0; i < 300; ++i) {
    NavSolution s;
    s.header = {kT0 + i * 5'000'000LL, TimeSource::kGps, 0,
                NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
                    NavSolution::kValidHeading | NavSolution::kValidPositionStd | NavSolution::kValidVelocityStd |
                    NavSolution::kValidAttitudeStd};
    s.mode = NavMode::kNavigation;
    s.gnss_fix = GnssFixType::kFix3D;
    s.lat_rad = uni(rng, -1.5, 1.5);
    s.lon_rad = uni(rng, -3.1, 3.1);
    s.height_m = uni(rng, -100, 9000);
    s.vel_ned_mps = vec(rng, -80, 80);
    s.vel_body_mps = vec(rng, -80, 80);
    s.rpy_rad = Eigen::Vector3d(uni(rng, -3, 3), uni(rng, -1.4, 1.4), uni(rng, -3.1, 3.1));
    s.q_nb = rot::quat_from_rpy(s.rpy_rad);
    const double pos_std = uni(rng, 0.01, 20), vel_std = uni(rng, 0.01, 2);
    s.pos_std_ned_m.setConstant(pos_std);
    s.vel_std_ned_mps.setConstant(vel_std);
    s.att_std_rpy_rad = vec(rng, 0.001, 0.1);
    s.status_flags = (i % 2) ? NavSolution::kStatusDualAntennaHeading : 0u;
    const auto out = h.round_trip(s);
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<NavSolution>(out[0]);
    EXPECT_EQ(d.header.time_ns, s.header.time_ns);
    EXPECT_EQ(d.header.valid, s.header.valid);
    EXPECT_EQ(d.mode, s.mode);
    EXPECT_EQ(d.gnss_fix, s.gnss_fix);
    EXPECT_EQ(d.status_flags, s.status_flags);
    EXPECT_DOUBLE_EQ(d.lat_rad, s.lat_rad * rot::kRadToDeg * rot::kDegToRad);
    EXPECT_NEAR(d.lat_rad, s.lat_rad, 1e-15);
    EXPECT_NEAR(d.lon_rad, s.lon_rad, 1e-15);
    EXPECT_DOUBLE_EQ(d.height_m, s.height_m);
    expect_near_rel(d.vel_ned_mps, s.vel_ned_mps, 80);
    expect_near_rel(d.vel_body_mps, s.vel_body_mps, 80);
    expect_near_rel(d.rpy_rad, s.rpy_rad, 3.2);
    EXPECT_NEAR(d.q_nb.angularDistance(s.q_nb), 0.0, 1e-6);
    expect_near_rel(d.pos_std_ned_m, s.pos_std_ned_m, 20);
    expect_near_rel(d.vel_std_ned_mps, s.vel_std_ned_mps, 2);
    expect_near_rel(d.att_std_rpy_rad, s.att_std_rpy_rad, 0.1);
  }
}

TEST(VnMeasurementRoundTrip, SolutionModesMapBothWays) {
  Harness h;
  const std::pair<NavMode, NavMode> cases[] = {
      {NavMode::kNavigation, NavMode::kNavigation}, {NavMode::kDeadReckoning, NavMode::kDeadReckoning},
      {NavMode::kInitializing, NavMode::kInitializing}, {NavMode::kAhrs, NavMode::kAhrs},
      {NavMode::kInvalid, NavMode::kInvalid},
      // VN has no vertical-gyro mode: NotTracking with an attitude reads back as AHRS.
      {NavMode::kVerticalGyro, NavMode::kAhrs}};
  for (const auto& [in, expected] : cases) {
    NavSolution s;
    s.header = {kT0, TimeSource::kGps, 0, 0};
    s.mode = in;
    s.gnss_fix = GnssFixType::kFix3D;
    if (in != NavMode::kInvalid) s.rpy_rad = {0.1, 0.2, 0.3};
    s.q_nb = rot::quat_from_rpy(s.rpy_rad);
    const auto out = h.round_trip(s);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(std::get<NavSolution>(out[0]).mode, expected) << to_string(in);
  }
}

TEST(VnMeasurementRoundTrip, GnssPositionAndVelocityPerReceiver) {
  std::mt19937_64 rng(13);
  Harness h;
  const GnssFixType fixes[] = {GnssFixType::kFix2D, GnssFixType::kFix3D, GnssFixType::kSbas,
                               GnssFixType::kRtkFloat, GnssFixType::kRtkFixed};
  for (int i = 0; i < 300; ++i) {
    GnssPosition p;
    p.header = {kT0 + i * 200'000'000LL, TimeSource::kGps, 0, 0};
    p.receiver_id = static_cast<std::uint8_t>(i % 3);
    p.fix = fixes[i % 5];
    p.header.valid = GnssPosition::kValidPosition | GnssPosition::kValidCovariance |
                     (p.fix == GnssFixType::kFix2D ? 0u : GnssPosition::kValidHeight);
    p.lat_rad = uni(rng, -1.5, 1.5);
    p.lon_rad = uni(rng, -3.1, 3.1);
    p.height_m = uni(rng, -100, 9000);
    p.num_sats = static_cast<std::uint8_t>(rng() % 40);
    const Eigen::Vector3d sd = vec(rng, 0.01, 10);
    p.cov_ned_m2 = sd.cwiseProduct(sd).asDiagonal();
    auto out = h.round_trip(p);
    ASSERT_EQ(out.size(), 1u);
    const auto& dp = std::get<GnssPosition>(out[0]);
    EXPECT_EQ(dp.header.time_ns, p.header.time_ns);
    EXPECT_EQ(dp.header.valid, p.header.valid);
    EXPECT_EQ(dp.receiver_id, p.receiver_id);
    EXPECT_EQ(dp.fix, p.fix);
    EXPECT_EQ(dp.num_sats, p.num_sats);
    EXPECT_NEAR(dp.lat_rad, p.lat_rad, 1e-15);
    EXPECT_DOUBLE_EQ(dp.height_m, p.height_m);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(dp.cov_ned_m2(k, k), p.cov_ned_m2(k, k), p.cov_ned_m2(k, k) * 1e-6);

    GnssVelocity v;
    v.header = {p.header.time_ns, TimeSource::kGps, 0, GnssVelocity::kValidVelocity | GnssVelocity::kValidCovariance};
    v.receiver_id = p.receiver_id;
    v.fix = p.fix;
    v.vel_ned_mps = vec(rng, -100, 100);
    v.cov_ned_m2ps2 = Eigen::Matrix3d::Identity() * 0.04;
    out = h.round_trip(v);
    ASSERT_EQ(out.size(), 1u);  // same epoch as the position, but a velocity: not a repeat
    const auto& dv = std::get<GnssVelocity>(out[0]);
    EXPECT_EQ(dv.header.time_ns, v.header.time_ns);
    EXPECT_EQ(dv.header.valid, v.header.valid);
    EXPECT_EQ(dv.receiver_id, v.receiver_id);
    expect_near_rel(dv.vel_ned_mps, v.vel_ned_mps, 100);
    EXPECT_NEAR(dv.cov_ned_m2ps2(1, 1), 0.04, 1e-8);
  }
}

TEST(VnMeasurementRoundTrip, CompassHeadingAndVehicleSpeedTakeTheLatestTime) {
  std::mt19937_64 rng(14);
  Harness h;
  for (int i = 0; i < 100; ++i) {
    // The ASCII outputs carry no time: they take the time of the binary message before them.
    ImuSample s;
    s.header = {kT0 + i * 5'000'000LL, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
    h.round_trip(s);
    GnssHeading g;
    g.header = {s.header.time_ns, TimeSource::kGps, 0, GnssHeading::kValidHeading};
    g.heading_rad = uni(rng, -3.14, 3.14);
    auto out = h.round_trip(g);
    ASSERT_EQ(out.size(), 1u);
    const auto& dg = std::get<GnssHeading>(out[0]);
    EXPECT_EQ(dg.header.time_ns, g.header.time_ns);
    EXPECT_EQ(dg.header.valid, g.header.valid);
    EXPECT_NEAR(dg.heading_rad, g.heading_rad, 0.0005 * rot::kDegToRad);  // printed to 1e-3 deg
    EXPECT_NEAR(dg.heading_std_rad, 1.45 * rot::kDegToRad, 1e-12);

    VehicleSpeed v;
    v.header = {s.header.time_ns, TimeSource::kGps, 0, VehicleSpeed::kValidSpeed};
    v.speed_mps = uni(rng, 0, 60);
    out = h.round_trip(v);
    ASSERT_EQ(out.size(), 1u);
    const auto& dv = std::get<VehicleSpeed>(out[0]);
    EXPECT_EQ(dv.header.time_ns, v.header.time_ns);
    EXPECT_NEAR(dv.speed_mps, v.speed_mps, 0.00005);  // printed to 1e-4 m/s
  }
}

TEST(VnMeasurementRoundTrip, KindsTheProtocolCannotCarry) {
  VnMeasurementEncoder e;
  std::vector<std::uint8_t> out;
  EXPECT_FALSE(e.encode(WheelSpeeds{}, out));
  EXPECT_FALSE(e.encode(WheelTicks{}, out));
  EXPECT_FALSE(e.encode(ExternalPosition{}, out));
  GnssPosition p;
  p.receiver_id = 3;
  EXPECT_FALSE(e.encode(p, out));
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace navfuse::frontends::vectornav

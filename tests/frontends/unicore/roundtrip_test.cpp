// decode(encode(m)) reproduces m to the protocol's resolution, for every measurement kind the
// UM220 carries, and a simulated drive decodes to exactly the measurement counts put in.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/unicore/decoder.hpp"
#include "frontends/unicore/encoder.hpp"
#include "frontends/unicore/to_core.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::unicore {
namespace {

using test::CollectingSink;

constexpr double kDeg = rot::kDegToRad;
// Resolutions of the printed formats (encoder.cpp): 1e-6 rad/s and m/s^2, 1e-6 deg NAVPOS,
// 1 mm/s NAVVEL, 1e-5 deg NAVATT, 0.01 s GGA/NAVATT time, 0.1 m h51 GGA height.
constexpr double kImuTol = 0.5e-6 + 1e-12;
constexpr double kNavposDegTol = 0.5e-6 + 1e-12;
constexpr double kVelTol = 1e-3;  // ECEF rounding of 0.5 mm/s per axis, rotated
constexpr double kAttTol = 0.5e-5 * kDeg + 1e-12;

struct Drive {
  std::vector<Measurement> in;
  std::map<MeasurementKind, std::size_t> counts;
};

// A 30 s drive: IMU at 10 Hz in the module frame with the odometer ticking, GNSS position /
// velocity and the device solution (GGA + NAVATT) at 1 Hz.
Drive simulate(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Drive d;
  const std::int64_t t0 = *time::gps_ns_from_utc({2024, 3, 9, 23, 59, 45.0});  // crosses midnight
  std::uint32_t ticks = 1000;
  for (int k = 0; k < 300; ++k) {
    const std::int64_t t = t0 + k * 100'000'000LL;
    ticks += static_cast<std::uint32_t>(20 + k % 7);
    WheelTicks w;
    w.header = {t, TimeSource::kGps, 0, WheelTicks::kValidFrontLeft};
    w.ticks[0] = ticks;
    w.channels = 1;
    w.gear = Gear::kForward;
    d.in.push_back(w);
    ImuSample s;
    s.header = {t, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
    s.gyro = {0.1 * u(rng), 0.1 * u(rng), 0.3 * u(rng)};
    s.accel = {u(rng), u(rng), -9.81 + 0.1 * u(rng)};
    s.dt_s = 0.1;
    s.low_rate = true;
    d.in.push_back(s);
    if (k % 10 != 0) continue;
    GnssPosition p;
    p.header = {t, TimeSource::kGps, 0, GnssPosition::kValidPosition | GnssPosition::kValidHeight |
                                            GnssPosition::kValidCovariance};
    p.lat_rad = (40.0 + 0.01 * u(rng)) * kDeg;
    p.lon_rad = (116.0 + 0.01 * u(rng)) * kDeg;
    p.height_m = 50.0 + u(rng);
    p.cov_ned_m2 = Eigen::Vector3d(0.5, 0.5, 2.0).asDiagonal();
    p.fix = GnssFixType::kFix3D;
    d.in.push_back(p);
    GnssVelocity v;
    v.header = {t, TimeSource::kGps, 0, GnssVelocity::kValidVelocity};
    v.vel_ned_mps = {10.0 * u(rng), 10.0 * u(rng), 0.5 * u(rng)};
    v.fix = GnssFixType::kFix3D;
    d.in.push_back(v);
    NavSolution n;
    n.header = {t, TimeSource::kGps, 0, NavSolution::kValidPosition | NavSolution::kValidAttitude |
                                            NavSolution::kValidAttitudeStd | NavSolution::kValidHeading};
    n.mode = NavMode::kNavigation;
    n.gnss_fix = GnssFixType::kFix3D;
    n.lat_rad = p.lat_rad;
    n.lon_rad = p.lon_rad;
    n.height_m = p.height_m;
    n.rpy_rad = {2.0 * u(rng) * kDeg, 2.0 * u(rng) * kDeg, 179.0 * u(rng) * kDeg};
    n.att_std_rpy_rad = {0.1 * kDeg, 0.1 * kDeg, 0.5 * kDeg};
    d.in.push_back(n);
  }
  for (const auto& m : d.in) ++d.counts[kind_of(m)];
  return d;
}

std::vector<std::uint8_t> encode_all(const std::vector<Measurement>& in, EncoderOptions opt = {}) {
  UnicoreEncoder enc(opt);
  std::vector<std::uint8_t> out;
  for (const auto& m : in) EXPECT_TRUE(enc.encode(m, out));
  return out;
}

TEST(UnicoreRoundTrip, SimulatedDriveDecodesToWhatWasPutIn) {
  const Drive d = simulate(1);
  const auto bytes = encode_all(d.in);
  UnicoreDecoder dec;
  CollectingSink sink;
  dec.feed(bytes, sink);
  dec.finish(sink);
  EXPECT_EQ(dec.counters().bad_frames, 0u);
  EXPECT_EQ(dec.counters().skipped_bytes, 0u);
  EXPECT_EQ(dec.counters().decode_errors, 0u);
  EXPECT_EQ(dec.counters().unknown_frames, 0u);
  EXPECT_EQ(sink.count(MeasurementKind::kImu), d.counts.at(MeasurementKind::kImu));
  EXPECT_EQ(sink.count(MeasurementKind::kWheelTicks), d.counts.at(MeasurementKind::kWheelTicks));
  EXPECT_EQ(sink.count(MeasurementKind::kGnssPosition), d.counts.at(MeasurementKind::kGnssPosition));
  EXPECT_EQ(sink.count(MeasurementKind::kGnssVelocity), d.counts.at(MeasurementKind::kGnssVelocity));
  // Each NavSolution is written as GGA (position) + NAVATT (attitude): two device solutions.
  EXPECT_EQ(sink.count(MeasurementKind::kDeviceSolution), 2 * d.counts.at(MeasurementKind::kDeviceSolution));

  // Values, matched in order per kind.
  std::map<MeasurementKind, std::vector<const Measurement*>> by_kind_in, by_kind_out;
  for (const auto& m : d.in) by_kind_in[kind_of(m)].push_back(&m);
  for (const auto& m : sink.measurements) by_kind_out[kind_of(m)].push_back(&m);
  for (std::size_t i = 0; i < by_kind_in[MeasurementKind::kImu].size(); ++i) {
    const auto& a = std::get<ImuSample>(*by_kind_in[MeasurementKind::kImu][i]);
    const auto& b = std::get<ImuSample>(*by_kind_out[MeasurementKind::kImu][i]);
    EXPECT_EQ(b.header.time_ns, a.header.time_ns);  // ms resolution, sim on whole ms
    EXPECT_LE((a.gyro - b.gyro).cwiseAbs().maxCoeff(), kImuTol);
    EXPECT_LE((a.accel - b.accel).cwiseAbs().maxCoeff(), kImuTol);
    EXPECT_DOUBLE_EQ(b.dt_s, a.dt_s);
    EXPECT_TRUE(b.low_rate);
  }
  for (std::size_t i = 0; i < by_kind_in[MeasurementKind::kWheelTicks].size(); ++i) {
    const auto& a = std::get<WheelTicks>(*by_kind_in[MeasurementKind::kWheelTicks][i]);
    const auto& b = std::get<WheelTicks>(*by_kind_out[MeasurementKind::kWheelTicks][i]);
    // Cumulative counts from per-period pulses: exact up to the first count (the decoder's
    // counter starts at 0).
    EXPECT_EQ(b.ticks[0] - std::get<WheelTicks>(*by_kind_out[MeasurementKind::kWheelTicks][0]).ticks[0],
              a.ticks[0] - std::get<WheelTicks>(*by_kind_in[MeasurementKind::kWheelTicks][0]).ticks[0]);
    EXPECT_EQ(b.gear, Gear::kForward);
    EXPECT_NEAR(b.period_s, 0.1, 1e-12);
  }
  for (std::size_t i = 0; i < by_kind_in[MeasurementKind::kGnssPosition].size(); ++i) {
    const auto& a = std::get<GnssPosition>(*by_kind_in[MeasurementKind::kGnssPosition][i]);
    const auto& b = std::get<GnssPosition>(*by_kind_out[MeasurementKind::kGnssPosition][i]);
    EXPECT_EQ(b.header.time_ns, a.header.time_ns);
    EXPECT_NEAR(b.lat_rad / kDeg, a.lat_rad / kDeg, kNavposDegTol);
    EXPECT_NEAR(b.lon_rad / kDeg, a.lon_rad / kDeg, kNavposDegTol);
    EXPECT_NEAR(b.height_m, a.height_m, 0.5e-6 + 1e-9);
    EXPECT_EQ(b.fix, a.fix);
    ASSERT_TRUE(b.header.valid & GnssPosition::kValidCovariance);
    // NAVACC carries the 2-D horizontal RMS: sqrt(0.5 + 0.5) = 1 m -> 0.5 m^2 per axis.
    EXPECT_NEAR(b.cov_ned_m2(0, 0), 0.5, 1e-6);
    EXPECT_NEAR(b.cov_ned_m2(1, 1), 0.5, 1e-6);
  }
  for (std::size_t i = 0; i < by_kind_in[MeasurementKind::kGnssVelocity].size(); ++i) {
    const auto& a = std::get<GnssVelocity>(*by_kind_in[MeasurementKind::kGnssVelocity][i]);
    const auto& b = std::get<GnssVelocity>(*by_kind_out[MeasurementKind::kGnssVelocity][i]);
    EXPECT_EQ(b.header.time_ns, a.header.time_ns);
    EXPECT_LE((a.vel_ned_mps - b.vel_ned_mps).norm(), kVelTol);
  }
  const auto& sols = by_kind_out[MeasurementKind::kDeviceSolution];
  for (std::size_t i = 0; i < by_kind_in[MeasurementKind::kDeviceSolution].size(); ++i) {
    const auto& a = std::get<NavSolution>(*by_kind_in[MeasurementKind::kDeviceSolution][i]);
    const auto& gga = std::get<NavSolution>(*sols[2 * i]);
    const auto& att = std::get<NavSolution>(*sols[2 * i + 1]);
    EXPECT_EQ(gga.header.time_ns, a.header.time_ns);
    EXPECT_EQ(att.header.time_ns, a.header.time_ns);
    EXPECT_EQ(gga.mode, NavMode::kNavigation);
    // h51 GGA: 6 minute decimals (1.7e-8 deg/2), height to 0.1 m.
    EXPECT_NEAR(gga.lat_rad / kDeg, a.lat_rad / kDeg, 0.5e-6 / 60.0 + 1e-12);
    EXPECT_NEAR(gga.lon_rad / kDeg, a.lon_rad / kDeg, 0.5e-6 / 60.0 + 1e-12);
    EXPECT_NEAR(gga.height_m, a.height_m, 0.05 + 1e-9);
    ASSERT_TRUE(att.header.valid & NavSolution::kValidAttitude);
    ASSERT_TRUE(att.header.valid & NavSolution::kValidHeading);
    EXPECT_LE((att.rpy_rad - a.rpy_rad).cwiseAbs().maxCoeff(), kAttTol);
    EXPECT_LE((att.att_std_rpy_rad - a.att_std_rpy_rad).cwiseAbs().maxCoeff(), kAttTol);
    EXPECT_EQ(att.mode, NavMode::kNavigation);  // taken from the GGA just before
  }
}

TEST(UnicoreRoundTrip, VehicleFrameImuAndIncrements) {
  const std::int64_t t = *time::gps_ns_from_utc({2023, 6, 1, 12, 0, 0.0});
  ImuSample s;
  s.header = {t, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
  s.frame = SensorFrame::kVehicle;
  s.gyro = {0.01, -0.02, 0.03};
  s.accel = {1.0, -2.0, -9.8};
  s.dt_s = 0.2;
  ImuSample inc = s;
  inc.frame = SensorFrame::kSensor;
  inc.quantity = ImuQuantity::kIncrements;
  inc.header.time_ns += 200'000'000;
  inc.gyro *= 0.2;
  inc.accel *= 0.2;
  const auto bytes = encode_all({s, inc});
  const std::string text(bytes.begin(), bytes.end());
  EXPECT_NE(text.find("$GYOACC-V,010623,120000.000,-0.020000,0.010000,-0.030000,200,"), std::string::npos)
      << text;  // FRD (x fwd, y right, z down) -> right, forward, up
  UnicoreDecoder dec;
  CollectingSink sink;
  dec.feed(bytes, sink);
  ASSERT_EQ(sink.count(MeasurementKind::kImu), 2u);
  const auto& a = std::get<ImuSample>(sink.measurements[0]);
  EXPECT_EQ(a.frame, SensorFrame::kVehicle);
  EXPECT_LE((a.gyro - s.gyro).cwiseAbs().maxCoeff(), kImuTol);
  EXPECT_LE((a.accel - s.accel).cwiseAbs().maxCoeff(), kImuTol);
  const auto& b = std::get<ImuSample>(sink.measurements[1]);
  EXPECT_EQ(b.quantity, ImuQuantity::kRates);
  EXPECT_LE((b.gyro - s.gyro).cwiseAbs().maxCoeff(), kImuTol);
}

TEST(UnicoreRoundTrip, VehicleSpeedThroughPulses) {
  EncoderOptions eo;
  eo.odometer_m_per_pulse = 0.05;
  UnicoreEncoder enc(eo);
  std::vector<std::uint8_t> out;
  const std::int64_t t0 = *time::gps_ns_from_utc({2023, 6, 1, 12, 0, 0.0});
  VehicleSpeed v;
  v.header = {t0, TimeSource::kGps, 0, VehicleSpeed::kValidSpeed};
  v.speed_mps = -2.0;  // reversing at 2 m/s = 40 pulses/s of 5 cm
  v.is_signed = true;
  for (int k = 0; k <= 10; ++k) {
    v.header.time_ns = t0 + k * 100'000'000LL;
    EXPECT_TRUE(enc.encode(v, out));
    ImuSample s;
    s.header = {v.header.time_ns, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
    s.dt_s = 0.1;
    EXPECT_TRUE(enc.encode(s, out));
  }
  DecoderOptions opt;
  opt.odometer_m_per_pulse = 0.05;
  UnicoreDecoder dec(opt);
  CollectingSink sink;
  dec.feed(out, sink);
  std::vector<double> speeds;
  for (const auto& m : sink.measurements) {
    if (kind_of(m) == MeasurementKind::kVehicleSpeed) speeds.push_back(std::get<VehicleSpeed>(m).speed_mps);
  }
  ASSERT_EQ(speeds.size(), 11u);
  for (std::size_t k = 1; k < speeds.size(); ++k) EXPECT_NEAR(speeds[k], -2.0, 1e-9) << k;
  // Without a scale the encoder cannot turn a speed into pulses.
  UnicoreEncoder plain;
  EXPECT_FALSE(plain.encode(v, out));
}

TEST(UnicoreRoundTrip, UnsupportedKindsAndVelocityWithoutPositionAreRefused) {
  UnicoreEncoder enc;
  std::vector<std::uint8_t> out;
  EXPECT_FALSE(enc.encode(Measurement{Magnetometer{}}, out));
  EXPECT_FALSE(enc.encode(Measurement{ExternalHeading{}}, out));
  GnssVelocity v;
  v.header.time_ns = *time::gps_ns_from_utc({2023, 6, 1, 12, 0, 0.0});
  EXPECT_FALSE(enc.encode(Measurement{v}, out));
  ImuSample bad;
  bad.gyro.x() = std::nan("");
  EXPECT_FALSE(enc.encode(Measurement{bad}, out));
  EXPECT_TRUE(out.empty());
}

TEST(UnicoreRoundTrip, DeadReckoningAndStdThroughGgaAndGst) {
  NavSolution n;
  n.header = {*time::gps_ns_from_utc({2023, 6, 1, 12, 0, 0.5}), TimeSource::kGps, 0,
              NavSolution::kValidPosition | NavSolution::kValidPositionStd};
  n.mode = NavMode::kDeadReckoning;
  n.lat_rad = -33.5 * kDeg;
  n.lon_rad = -70.25 * kDeg;
  n.height_m = 512.3;
  n.pos_std_ned_m = {1.25, 2.5, 4.75};
  n.device_status = pack_snrstat(Snrstat{3, 2, 0, -1});
  for (auto dialect : {nmea::Dialect::kH51, nmea::Dialect::kH30}) {
    EncoderOptions eo;
    eo.dialect = dialect;
    const auto bytes = encode_all({n}, eo);
    UnicoreDecoder dec;
    CollectingSink sink;
    dec.feed(bytes, sink);
    ASSERT_EQ(sink.count(MeasurementKind::kDeviceSolution), 1u);
    const auto& s = std::get<NavSolution>(sink.measurements[0]);
    EXPECT_EQ(s.mode, NavMode::kDeadReckoning);  // GGA FS = 6 (L882)
    EXPECT_TRUE(s.status_flags & NavSolution::kStatusGnssOutage);
    EXPECT_TRUE(s.status_flags & NavSolution::kStatusWheelAiding);  // odostatus 2
    EXPECT_EQ(s.device_status, n.device_status);
    EXPECT_NEAR(s.lat_rad / kDeg, -33.5, 1e-9);
    EXPECT_NEAR(s.lon_rad / kDeg, -70.25, 1e-9);
    EXPECT_NEAR(s.height_m, 512.3, 1e-9);
    ASSERT_TRUE(s.header.valid & NavSolution::kValidPositionStd);
    EXPECT_NEAR(s.pos_std_ned_m.x(), 1.25, 1e-9);
    EXPECT_NEAR(s.pos_std_ned_m.z(), 4.75, 1e-9);
    EXPECT_EQ(dec.dialect(), nmea::Dialect::kH51);  // GGA/GST do not tell the dialect apart
  }
}

}  // namespace
}  // namespace navfuse::frontends::unicore

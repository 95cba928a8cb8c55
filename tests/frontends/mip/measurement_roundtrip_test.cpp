// decode(encode(m)) == m to MIP resolution, randomised, for every measurement kind the MIP
// encoder carries; the kinds MIP cannot carry are refused.
#include <gtest/gtest.h>

#include <random>

#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/mip/decoder.hpp"
#include "frontends/mip/encoder.hpp"
#include "tests/frontends/mip/test_util.hpp"

namespace navfuse::frontends::mip {
namespace {

constexpr double kF32Rel = 2e-7;  // float32 relative resolution (2^-23 ~ 1.2e-7, plus g scaling)

class MipMeasurementRoundTrip : public ::testing::Test {
 protected:
  std::mt19937 rng{99};
  double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  Eigen::Vector3d vec(double a) { return {uni(-a, a), uni(-a, a), uni(-a, a)}; }
  MeasurementHeader header() {
    MeasurementHeader h;
    // A GPS time in 2024-2026 with microsecond detail (tow is a float64 on the wire).
    h.time_ns = time::gps_ns_from_week_tow(2300 + static_cast<int>(uni(0, 100)), 0) +
                static_cast<std::int64_t>(uni(0, 604799)) * 1'000'000'000 + static_cast<std::int64_t>(uni(0, 1e6)) * 1000;
    h.time_source = TimeSource::kGps;
    return h;
  }
  std::vector<Measurement> roundtrip(const Measurement& m) {
    MipEncoder enc;
    std::vector<std::uint8_t> bytes;
    EXPECT_TRUE(enc.encode(m, bytes));
    MipDecoder dec;
    test::CollectingSink sink;
    dec.feed(bytes, sink);
    dec.finish(sink);
    EXPECT_EQ(dec.counters().bad_frames, 0u);
    EXPECT_EQ(dec.counters().skipped_bytes, 0u);
    EXPECT_EQ(dec.counters().decode_errors, 0u);
    return sink.measurements;
  }
  static void near3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double rel = kF32Rel) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], rel * std::max(1.0, std::abs(b[i]))) << i;
  }
};

TEST_F(MipMeasurementRoundTrip, ImuRatesAndIncrements) {
  for (int trial = 0; trial < 200; ++trial) {
    ImuSample m;
    m.header = header();
    m.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
    m.frame = SensorFrame::kVehicle;
    m.quantity = trial % 2 ? ImuQuantity::kIncrements : ImuQuantity::kRates;
    m.gyro = vec(trial % 2 ? 0.05 : 5.0);
    m.accel = vec(trial % 2 ? 1.0 : 150.0);
    m.dt_s = 0.01;
    m.saturation = static_cast<std::uint8_t>(trial % 64);
    const auto out = roundtrip(m);
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<ImuSample>(out[0]);
    EXPECT_EQ(d.header.time_ns, m.header.time_ns);
    EXPECT_EQ(d.header.time_source, TimeSource::kGps);
    EXPECT_EQ(d.header.valid, m.header.valid);
    EXPECT_EQ(d.quantity, m.quantity);
    // Delta theta / delta velocity are time integrals (0x80 0x07/0x08): the filter compensates them.
    EXPECT_EQ(d.increments, ImuIncrements::kRawIntegrals);
    EXPECT_EQ(d.saturation, m.saturation);
    EXPECT_DOUBLE_EQ(d.dt_s, m.dt_s);
    near3(d.gyro, m.gyro);
    near3(d.accel, m.accel);
  }
}

TEST_F(MipMeasurementRoundTrip, MagnetometerPressureOdometer) {
  for (int trial = 0; trial < 100; ++trial) {
    Magnetometer mag;
    mag.header = header();
    mag.header.valid = Magnetometer::kValidField;
    mag.frame = SensorFrame::kVehicle;
    mag.field_gauss = vec(0.6);
    auto out = roundtrip(mag);
    ASSERT_EQ(out.size(), 1u);
    near3(std::get<Magnetometer>(out[0]).field_gauss, mag.field_gauss);

    Pressure p;
    p.header = header();
    p.header.valid = Pressure::kValidPressure;
    p.pressure_pa = uni(30000, 110000);
    out = roundtrip(p);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(std::get<Pressure>(out[0]).pressure_pa, p.pressure_pa, p.pressure_pa * kF32Rel);

    VehicleSpeed v;
    v.header = header();
    v.header.valid = VehicleSpeed::kValidSpeed;
    v.speed_mps = uni(-30, 30);
    v.is_signed = true;
    v.speed_std_mps = uni(0.01, 0.5);
    out = roundtrip(v);
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<VehicleSpeed>(out[0]);
    EXPECT_NEAR(d.speed_mps, v.speed_mps, 30 * kF32Rel);
    EXPECT_NEAR(d.speed_std_mps, v.speed_std_mps, kF32Rel);
    EXPECT_TRUE(d.is_signed);
    EXPECT_EQ(d.header.time_ns, v.header.time_ns);
  }
}

TEST_F(MipMeasurementRoundTrip, GnssPositionVelocityPerReceiver) {
  const GnssFixType fixes[] = {GnssFixType::kNone, GnssFixType::kTimeOnly, GnssFixType::kFix2D, GnssFixType::kFix3D,
                               GnssFixType::kDgnss, GnssFixType::kSbas, GnssFixType::kRtkFloat, GnssFixType::kRtkFixed};
  for (int trial = 0; trial < 120; ++trial) {
    GnssPosition p;
    p.header = header();
    p.header.valid = GnssPosition::kValidPosition | GnssPosition::kValidHeight | GnssPosition::kValidCovariance;
    p.lat_rad = uni(-1.5, 1.5);
    p.lon_rad = uni(-3.1, 3.1);
    p.height_m = uni(-100, 3000);
    const double h = uni(0.01, 5), v = uni(0.01, 8);
    p.cov_ned_m2 = Eigen::Vector3d(h * h, h * h, v * v).asDiagonal();
    p.fix = fixes[trial % 8];
    p.num_sats = static_cast<std::uint8_t>(trial % 40);
    p.receiver_id = static_cast<std::uint8_t>(trial % 3);
    auto out = roundtrip(p);
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<GnssPosition>(out[0]);
    EXPECT_NEAR(d.lat_rad, p.lat_rad, 1e-15);
    EXPECT_NEAR(d.lon_rad, p.lon_rad, 1e-15);
    EXPECT_DOUBLE_EQ(d.height_m, p.height_m);
    EXPECT_NEAR(d.cov_ned_m2(0, 0), p.cov_ned_m2(0, 0), 4 * kF32Rel * p.cov_ned_m2(0, 0));
    EXPECT_NEAR(d.cov_ned_m2(2, 2), p.cov_ned_m2(2, 2), 4 * kF32Rel * p.cov_ned_m2(2, 2));
    EXPECT_EQ(d.fix, p.fix);
    EXPECT_EQ(d.num_sats, p.num_sats);
    EXPECT_EQ(d.receiver_id, p.receiver_id);
    EXPECT_EQ(d.header.valid, p.header.valid);
    EXPECT_EQ(d.header.time_ns, p.header.time_ns);

    GnssVelocity gv;
    gv.header = header();
    gv.header.valid = GnssVelocity::kValidVelocity | GnssVelocity::kValidCovariance;
    gv.vel_ned_mps = vec(50);
    const double s = uni(0.01, 1);
    gv.cov_ned_m2ps2 = Eigen::Matrix3d::Identity() * s * s;
    gv.fix = fixes[(trial + 3) % 8];
    gv.receiver_id = static_cast<std::uint8_t>(trial % 3);
    out = roundtrip(gv);
    ASSERT_EQ(out.size(), 1u);
    const auto& dv = std::get<GnssVelocity>(out[0]);
    near3(dv.vel_ned_mps, gv.vel_ned_mps, 50 * kF32Rel);
    EXPECT_NEAR(dv.cov_ned_m2ps2(1, 1), s * s, 4 * kF32Rel);
    EXPECT_EQ(dv.fix, gv.fix);
    EXPECT_EQ(dv.receiver_id, gv.receiver_id);
  }
}

TEST_F(MipMeasurementRoundTrip, DualAntennaHeading) {
  for (int trial = 0; trial < 50; ++trial) {
    GnssHeading m;
    m.header = header();
    m.header.valid = GnssHeading::kValidHeading;
    m.heading_rad = uni(-3.1, 3.1);
    m.heading_std_rad = uni(0.001, 0.1);
    m.fix = trial % 2 ? GnssFixType::kRtkFixed : GnssFixType::kRtkFloat;
    const auto out = roundtrip(m);
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<GnssHeading>(out[0]);
    EXPECT_NEAR(d.heading_rad, m.heading_rad, 4 * kF32Rel);
    EXPECT_NEAR(d.heading_std_rad, m.heading_std_rad, kF32Rel);
    EXPECT_EQ(d.fix, m.fix);
    EXPECT_EQ(d.header.time_ns, m.header.time_ns);
  }
}

TEST_F(MipMeasurementRoundTrip, NavSolutionAsFilterPacketsWithContinuation) {
  const NavMode modes[] = {NavMode::kInitializing, NavMode::kVerticalGyro, NavMode::kAhrs, NavMode::kNavigation,
                           NavMode::kDeadReckoning};
  for (int trial = 0; trial < 100; ++trial) {
    NavSolution s;
    s.header = header();
    s.mode = modes[trial % 5];
    s.header.valid = NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
                     NavSolution::kValidPositionStd | NavSolution::kValidVelocityStd | NavSolution::kValidAttitudeStd |
                     NavSolution::kValidBiases;
    if (s.mode == NavMode::kAhrs || s.mode == NavMode::kNavigation || s.mode == NavMode::kDeadReckoning)
      s.header.valid |= NavSolution::kValidHeading;
    if (s.mode == NavMode::kDeadReckoning) s.status_flags |= NavSolution::kStatusGnssOutage;
    if (trial % 7 == 0) s.status_flags |= NavSolution::kStatusDiverged;
    s.lat_rad = uni(-1.4, 1.4);
    s.lon_rad = uni(-3, 3);
    s.height_m = uni(-50, 5000);
    s.vel_ned_mps = vec(60);
    s.rpy_rad = {uni(-3, 3), uni(-1.4, 1.4), uni(-3, 3)};
    s.q_nb = rot::quat_from_rpy(s.rpy_rad);
    s.pos_std_ned_m = vec(5).cwiseAbs();
    s.vel_std_ned_mps = vec(1).cwiseAbs();
    s.att_std_rpy_rad = vec(0.1).cwiseAbs();
    s.gyro_bias_rps = vec(0.01);
    s.accel_bias_mps2 = vec(0.1);
    s.gyro_bias_std_rps = vec(0.001).cwiseAbs();
    s.accel_bias_std_mps2 = vec(0.01).cwiseAbs();
    s.angular_rate_rps = vec(2);
    s.linear_accel_mps2 = vec(20);
    s.gravity_ned_mps2 = {uni(-1e-4, 1e-4), uni(-1e-4, 1e-4), uni(9.77, 9.84)};
    MipEncoder enc;
    std::vector<std::uint8_t> bytes;
    ASSERT_TRUE(enc.encode(s, bytes));
    MipDecoder dec;
    test::CollectingSink sink;
    dec.feed(bytes, sink);
    dec.finish(sink);
    EXPECT_EQ(dec.counters().frames, 2u);  // 262 payload bytes: one continuation (L3974)
    ASSERT_EQ(sink.measurements.size(), 1u);
    const auto& d = std::get<NavSolution>(sink.measurements[0]);
    EXPECT_EQ(d.header.time_ns, s.header.time_ns);
    EXPECT_EQ(d.header.valid, s.header.valid);
    EXPECT_EQ(d.mode, s.mode);
    EXPECT_EQ(d.status_flags, s.status_flags);
    EXPECT_NEAR(d.lat_rad, s.lat_rad, 1e-15);
    EXPECT_NEAR(d.lon_rad, s.lon_rad, 1e-15);
    EXPECT_DOUBLE_EQ(d.height_m, s.height_m);
    near3(d.vel_ned_mps, s.vel_ned_mps, 60 * kF32Rel);
    near3(d.rpy_rad, s.rpy_rad, 4 * kF32Rel);
    EXPECT_NEAR(std::abs(d.q_nb.dot(s.q_nb)), 1.0, 1e-6);
    near3(d.pos_std_ned_m, s.pos_std_ned_m);
    near3(d.vel_std_ned_mps, s.vel_std_ned_mps);
    near3(d.att_std_rpy_rad, s.att_std_rpy_rad);
    near3(d.gyro_bias_rps, s.gyro_bias_rps);
    near3(d.accel_bias_mps2, s.accel_bias_mps2);
    near3(d.gyro_bias_std_rps, s.gyro_bias_std_rps);
    near3(d.accel_bias_std_mps2, s.accel_bias_std_mps2);
    near3(d.angular_rate_rps, s.angular_rate_rps, 2 * kF32Rel);
    near3(d.linear_accel_mps2, s.linear_accel_mps2, 20 * kF32Rel);
    near3(d.gravity_ned_mps2, s.gravity_ned_mps2, 1e-5);  // float vector rotated twice
  }
}

TEST_F(MipMeasurementRoundTrip, ExternalAidingAsCommands) {
  for (int trial = 0; trial < 60; ++trial) {
    ExternalPosition p;
    p.header = header();
    p.header.valid = static_cast<std::uint32_t>(1 + trial % 7);
    p.frame = trial % 2 ? PositionFrame::kEcef : PositionFrame::kLlh;
    p.value = p.frame == PositionFrame::kLlh ? Eigen::Vector3d(uni(-1.5, 1.5), uni(-3, 3), uni(0, 500))
                                             : Eigen::Vector3d(uni(-7e6, 7e6), uni(-7e6, 7e6), uni(-7e6, 7e6));
    p.std_m = Eigen::Vector3d(uni(0.1, 3), uni(0.1, 3), uni(0.1, 3));
    p.lever_arm_m = trial % 3 ? Eigen::Vector3d(uni(-2, 2), uni(-2, 2), uni(-2, 2)) : Eigen::Vector3d::Zero();
    auto out = roundtrip(p);
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<ExternalPosition>(out[0]);
    EXPECT_EQ(d.frame, p.frame);
    EXPECT_EQ(d.header.valid, p.header.valid);
    EXPECT_EQ(d.header.time_ns, p.header.time_ns);
    for (int i = 0; i < 3; ++i)
      if (p.header.valid & (1u << i)) {
        EXPECT_NEAR(d.value[i], p.value[i], 1e-9 * std::max(1.0, std::abs(p.value[i])));
        EXPECT_NEAR(d.std_m[i], p.std_m[i], 4 * kF32Rel);
      }
    near3(d.lever_arm_m, p.lever_arm_m, 4 * kF32Rel);

    ExternalVelocity v;
    v.header = header();
    v.header.valid = static_cast<std::uint32_t>(1 + trial % 7);
    v.frame = static_cast<VelocityFrame>(trial % 3);
    v.value_mps = vec(30);
    v.std_mps = vec(0.5).cwiseAbs() + Eigen::Vector3d::Constant(0.01);
    out = roundtrip(v);
    ASSERT_EQ(out.size(), 1u);
    const auto& dv = std::get<ExternalVelocity>(out[0]);
    EXPECT_EQ(dv.frame, v.frame);
    EXPECT_EQ(dv.header.valid, v.header.valid);
    for (int i = 0; i < 3; ++i)
      if (v.header.valid & (1u << i)) {
        EXPECT_NEAR(dv.value_mps[i], v.value_mps[i], 30 * kF32Rel);
      }

    ExternalHeading h;
    h.header = header();
    h.header.valid = ExternalHeading::kValidHeading;
    h.heading_rad = uni(-3.1, 3.1);
    h.std_rad = uni(0.01, 0.2);
    out = roundtrip(h);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(std::get<ExternalHeading>(out[0]).heading_rad, h.heading_rad, 4 * kF32Rel);
  }
}

TEST_F(MipMeasurementRoundTrip, KindsWithoutMipCarrierAreRefused) {
  MipEncoder enc;
  std::vector<std::uint8_t> out;
  EXPECT_FALSE(enc.encode(WheelSpeeds{}, out));
  EXPECT_FALSE(enc.encode(WheelTicks{}, out));
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace navfuse::frontends::mip

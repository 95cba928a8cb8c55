// decode(encode(m)) == m to FusionEngine's resolution, for every measurement kind the encoder
// carries, with randomised values; plus the frame conventions checked against hand-derived
// values (digest §9: heading = 90 - yaw, pitch sign flipped, FLU <-> FRD).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/geodesy/geoid.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/encoder.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

using rot::kDegToRad;

constexpr std::int64_t kT0 = 1'400'000'000'000'000'000;  // 2024, GPS ns

std::vector<Measurement> round_trip(const std::vector<Measurement>& in, const EncoderOptions& options = {}) {
  FusionEngineEncoder encoder(options);
  std::vector<std::uint8_t> bytes;
  for (const auto& m : in) EXPECT_TRUE(encoder.encode(m, bytes));
  FusionEngineDecoder decoder;
  test::CollectingSink sink;
  decoder.feed(bytes, sink);
  decoder.finish(sink);
  EXPECT_EQ(decoder.counters().bad_frames, 0u);
  EXPECT_EQ(decoder.counters().decode_errors, 0u);
  return sink.measurements;
}

double uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
Eigen::Vector3d vec(std::mt19937_64& rng, double lim) {
  return {uniform(rng, -lim, lim), uniform(rng, -lim, lim), uniform(rng, -lim, lim)};
}
MeasurementHeader gps_header(std::int64_t t, std::uint32_t valid) { return {t, TimeSource::kGps, 0, valid}; }

TEST(FeMeasurementRoundTrip, ImuVehicleFrameIsExact) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 200; ++i) {
    ImuSample imu;
    imu.header = gps_header(kT0 + std::int64_t{i} * 10'000'000, ImuSample::kValidGyro | ImuSample::kValidAccel);
    imu.frame = SensorFrame::kVehicle;
    imu.gyro = vec(rng, 5.0);
    imu.accel = vec(rng, 50.0);
    const auto out = round_trip({imu});
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<ImuSample>(out[0]);
    // IMUOutput carries only P1 time; with no Pose yet to relate P1 to GPS it is kept as the
    // device clock (navfuse writes P1 = GPS time, so the value is the same).
    EXPECT_EQ(d.header.time_ns, imu.header.time_ns);
    EXPECT_EQ(d.header.time_source, TimeSource::kDeviceMonotonic);
    EXPECT_EQ(d.frame, SensorFrame::kVehicle);
    EXPECT_EQ(d.gyro, imu.gyro);
    EXPECT_EQ(d.accel, imu.accel);
    EXPECT_EQ(d.header.valid, imu.header.valid);
  }
}

TEST(FeMeasurementRoundTrip, ImuSensorFrameToScaledIntegerResolution) {
  std::mt19937_64 rng(2);
  for (bool inputs : {false, true}) {
    for (int i = 0; i < 200; ++i) {
      ImuSample imu;
      imu.header = gps_header(kT0 + std::int64_t{i} * 5'000'000, ImuSample::kValidGyro | ImuSample::kValidAccel);
      imu.frame = SensorFrame::kSensor;
      imu.gyro = vec(rng, 10.0);
      imu.accel = vec(rng, 150.0);
      const auto out = round_trip({imu}, {.sensor_inputs = inputs});
      ASSERT_EQ(out.size(), 1u);
      const auto& d = std::get<ImuSample>(out[0]);
      EXPECT_EQ(d.header.time_ns, imu.header.time_ns);
      EXPECT_EQ(d.header.time_source, TimeSource::kGps);  // MeasurementDetails carries GPS time
      EXPECT_EQ(d.frame, SensorFrame::kSensor);
      // Half an LSB: 2^-21 rad/s and 2^-17 m/s^2 (spec L2313-2318).
      EXPECT_LE((d.gyro - imu.gyro).cwiseAbs().maxCoeff(), 0.5 / 1048576.0 + 1e-15);
      EXPECT_LE((d.accel - imu.accel).cwiseAbs().maxCoeff(), 0.5 / 65536.0 + 1e-12);
    }
  }
}

TEST(FeMeasurementRoundTrip, DeviceSolutionThroughPosePoseAuxAndGnssInfo) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 200; ++i) {
    NavSolution s;
    s.header = gps_header(kT0 + std::int64_t{i} * 100'000'000, NavSolution::kValidPosition | NavSolution::kValidVelocity |
                                                     NavSolution::kValidAttitude | NavSolution::kValidHeading |
                                                     NavSolution::kValidPositionStd | NavSolution::kValidVelocityStd |
                                                     NavSolution::kValidAttitudeStd | NavSolution::kValidUndulation);
    s.mode = NavMode::kNavigation;
    s.gnss_fix = (i % 2) ? GnssFixType::kRtkFixed : GnssFixType::kRtkFloat;
    s.lat_rad = uniform(rng, -1.4, 1.4);
    s.lon_rad = uniform(rng, -3.1, 3.1);
    s.height_m = uniform(rng, -100, 3000);
    s.undulation_m = uniform(rng, -100, 80);
    s.vel_ned_mps = vec(rng, 30);
    s.rpy_rad = {uniform(rng, -1, 1), uniform(rng, -1.2, 1.2), uniform(rng, -3.1, 3.1)};
    s.q_nb = rot::quat_from_rpy(s.rpy_rad);
    s.pos_std_ned_m = {uniform(rng, 0.01, 5), uniform(rng, 0.01, 5), uniform(rng, 0.01, 5)};
    s.vel_std_ned_mps = {uniform(rng, 0.01, 1), uniform(rng, 0.01, 1), uniform(rng, 0.01, 1)};
    s.att_std_rpy_rad = {uniform(rng, 0.001, 0.1), uniform(rng, 0.001, 0.1), uniform(rng, 0.001, 0.1)};
    if (i % 3 == 0) s.status_flags = NavSolution::kStatusStationary;
    const auto out = round_trip({s});
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<NavSolution>(out[0]);
    EXPECT_EQ(d.header.time_ns, s.header.time_ns);
    EXPECT_EQ(d.header.time_source, TimeSource::kGps);
    EXPECT_EQ(d.header.valid, s.header.valid);
    EXPECT_EQ(d.mode, s.mode);
    EXPECT_EQ(d.gnss_fix, s.gnss_fix);
    EXPECT_EQ(d.status_flags & NavSolution::kStatusStationary, s.status_flags & NavSolution::kStatusStationary);
    EXPECT_NEAR(d.lat_rad, s.lat_rad, 1e-15);
    EXPECT_NEAR(d.lon_rad, s.lon_rad, 1e-15);
    EXPECT_EQ(d.height_m, s.height_m);
    EXPECT_NEAR(d.undulation_m, s.undulation_m, 0.005 + 1e-12);  // cm resolution (L1736)
    EXPECT_LT((d.vel_ned_mps - s.vel_ned_mps).norm(), 1e-12);  // PoseAux ENU velocity, f64
    EXPECT_LT(d.q_nb.angularDistance(s.q_nb), 1e-9);
    EXPECT_LT((d.pos_std_ned_m - s.pos_std_ned_m).cwiseAbs().maxCoeff(), 1e-6);     // f32
    EXPECT_LT((d.vel_std_ned_mps - s.vel_std_ned_mps).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_LT((d.att_std_rpy_rad - s.att_std_rpy_rad).cwiseAbs().maxCoeff(), 1e-8);
  }
}

TEST(FeMeasurementRoundTrip, DeadReckoningAndAttitudeOnlySolutions) {
  NavSolution dr;
  dr.header = gps_header(kT0, NavSolution::kValidPosition);
  dr.mode = NavMode::kDeadReckoning;
  dr.lat_rad = 0.5;
  dr.lon_rad = 0.2;
  NavSolution ahrs;  // roll/pitch only: no heading, no position
  ahrs.header = gps_header(kT0 + 1'000'000, NavSolution::kValidAttitude);
  ahrs.mode = NavMode::kVerticalGyro;
  ahrs.rpy_rad = {0.1, -0.2, 0.0};
  ahrs.q_nb = rot::quat_from_rpy(ahrs.rpy_rad);
  const auto out = round_trip({dr, ahrs});
  ASSERT_EQ(out.size(), 2u);
  const auto& d0 = std::get<NavSolution>(out[0]);
  EXPECT_EQ(d0.mode, NavMode::kDeadReckoning);  // SolutionType Integrate (L1775)
  EXPECT_EQ(d0.gnss_fix, GnssFixType::kNone);
  EXPECT_NE(d0.header.valid & NavSolution::kValidPosition, 0u);
  const auto& d1 = std::get<NavSolution>(out[1]);
  EXPECT_EQ(d1.mode, NavMode::kInvalid);  // no position: SolutionType Invalid
  EXPECT_EQ(d1.header.valid & (NavSolution::kValidPosition | NavSolution::kValidHeading), 0u);
  EXPECT_NE(d1.header.valid & NavSolution::kValidAttitude, 0u);
  EXPECT_NEAR(d1.rpy_rad.x(), 0.1, 1e-12);
  EXPECT_NEAR(d1.rpy_rad.y(), -0.2, 1e-12);
}

TEST(FeMeasurementRoundTrip, GnssHeadingToFloatResolution) {
  std::mt19937_64 rng(4);
  for (int i = 0; i < 200; ++i) {
    GnssHeading h;
    h.header = gps_header(kT0 + i, GnssHeading::kValidHeading | GnssHeading::kValidPitch | GnssHeading::kValidBaseline);
    h.heading_rad = uniform(rng, -rot::kPi, rot::kPi);
    h.heading_std_rad = uniform(rng, 0.001, 0.05);
    h.pitch_rad = uniform(rng, -0.3, 0.3);
    h.pitch_std_rad = uniform(rng, 0.001, 0.05);
    h.baseline_m = uniform(rng, 0.5, 3.0);
    h.fix = GnssFixType::kRtkFixed;
    const auto out = round_trip({h});
    ASSERT_EQ(out.size(), 1u);
    const auto& d = std::get<GnssHeading>(out[0]);
    EXPECT_EQ(d.header.time_ns, h.header.time_ns);
    EXPECT_EQ(d.header.valid, h.header.valid);
    EXPECT_EQ(d.fix, GnssFixType::kRtkFixed);
    EXPECT_NEAR(rot::wrap_pi(d.heading_rad - h.heading_rad), 0.0, 1e-6);  // f32 degrees
    EXPECT_NEAR(d.heading_std_rad, h.heading_std_rad, 1e-8);
    EXPECT_NEAR(d.pitch_rad, h.pitch_rad, 1e-7);
    EXPECT_NEAR(d.baseline_m, h.baseline_m, 1e-6);
  }
}

TEST(FeMeasurementRoundTrip, WheelAndVehicleSpeedTo2PowMinus10) {
  std::mt19937_64 rng(5);
  for (bool inputs : {false, true}) {
    for (int i = 0; i < 100; ++i) {
      WheelSpeeds w;
      w.header = gps_header(kT0 + i, WheelSpeeds::kValidFrontLeft | WheelSpeeds::kValidRearLeft | WheelSpeeds::kValidRearRight);
      for (auto& s : w.speed_mps) s = uniform(rng, -40, 40);
      w.speed_mps[1] = 0.0;  // front right invalid: not carried
      w.gear = static_cast<Gear>(i % 5);
      w.is_signed = i % 2 == 0;
      VehicleSpeed v;
      v.header = gps_header(kT0 + i + 1, VehicleSpeed::kValidSpeed);
      v.speed_mps = uniform(rng, -40, 40);
      v.gear = Gear::kReverse;
      v.is_signed = true;
      const auto out = round_trip({w, v}, {.sensor_inputs = inputs});
      ASSERT_EQ(out.size(), 2u);
      const auto& dw = std::get<WheelSpeeds>(out[0]);
      EXPECT_EQ(dw.header.valid, w.header.valid);
      EXPECT_EQ(dw.gear, w.gear);
      EXPECT_EQ(dw.is_signed, w.is_signed);
      for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(dw.speed_mps[k], w.speed_mps[k], 0.5 / 1024 + 1e-12);
      const auto& dv = std::get<VehicleSpeed>(out[1]);
      EXPECT_EQ(dv.header.time_ns, v.header.time_ns);
      EXPECT_NEAR(dv.speed_mps, v.speed_mps, 0.5 / 1024 + 1e-12);
      EXPECT_EQ(dv.gear, Gear::kReverse);
      EXPECT_TRUE(dv.is_signed);
    }
  }
}

TEST(FeMeasurementRoundTrip, WheelAndVehicleTicksExact) {
  std::mt19937_64 rng(6);
  WheelTicks w;
  w.header = gps_header(kT0, WheelTicks::kValidFrontLeft | WheelTicks::kValidFrontRight |
                                 WheelTicks::kValidRearLeft | WheelTicks::kValidRearRight);
  for (auto& t : w.ticks) t = static_cast<std::uint32_t>(rng());
  w.gear = Gear::kForward;
  WheelTicks single;
  single.header = gps_header(kT0 + 5, WheelTicks::kValidFrontLeft);
  single.channels = 1;
  single.ticks = {123456u, 0, 0, 0};
  const auto out = round_trip({w, single});
  ASSERT_EQ(out.size(), 2u);
  const auto& d = std::get<WheelTicks>(out[0]);
  EXPECT_EQ(d.ticks, w.ticks);
  EXPECT_EQ(d.channels, 4);
  EXPECT_EQ(d.gear, Gear::kForward);
  EXPECT_EQ(d.rollover, 0u);  // no WheelConfig: 2^32
  const auto& s = std::get<WheelTicks>(out[1]);
  EXPECT_EQ(s.channels, 1);
  EXPECT_EQ(s.ticks[0], 123456u);
}

TEST(FeMeasurementRoundTrip, TickRolloverFollowsWheelConfig) {
  // Spec L1134: max value 10 -> signed counters span [-11, 10], unsigned [0, 10].
  WheelConfig config;
  config.wheel_sensor_type = static_cast<std::uint8_t>(WheelSensorType::kTicks);
  config.wheel_tick_max_value = 10;
  config.wheel_ticks_signed = 1;
  FusionEngineWriter w;
  std::vector<std::uint8_t> bytes;
  SetConfigMessage set;
  set.config_type = to_u16(ConfigType::kWheelConfig);
  set.value = pack_config(config);
  w.append(set, bytes);
  WheelTickInputMessage ticks;
  ticks.details.time_source = static_cast<std::uint8_t>(SystemTimeSource::kGpsTime);
  ticks.details.measurement_time = Timestamp::from_ns(kT0);
  ticks.ticks = {static_cast<std::uint32_t>(-11), static_cast<std::uint32_t>(-1), 10u, 0u};
  w.append(ticks, bytes);
  FusionEngineDecoder decoder;
  test::CollectingSink sink;
  decoder.feed(bytes, sink);
  decoder.finish(sink);
  const auto t = sink.all<WheelTicks>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].rollover, 22u);
  // -11 -> 11, -1 -> 21, 10 -> 10, 0 -> 0: differences modulo 22 are those of the signed values.
  EXPECT_EQ(t[0].ticks, (std::array<std::uint32_t, 4>{11u, 21u, 10u, 0u}));
  EXPECT_TRUE(t[0].is_signed);  // always_increase = 0: ticks decrease backward (L1160)
}

TEST(FeMeasurementRoundTrip, GnssFixesThroughRosGpsFix) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 100; ++i) {
    GnssPosition p;
    p.header = gps_header(kT0 + std::int64_t{i} * 1'000'000, GnssPosition::kValidPosition | GnssPosition::kValidHeight |
                                                   GnssPosition::kValidCovariance);
    p.lat_rad = uniform(rng, -1.4, 1.4);
    p.lon_rad = uniform(rng, -3.1, 3.1);
    p.height_m = uniform(rng, -50, 2000);
    const Eigen::Matrix3d a = Eigen::Matrix3d::Random();
    p.cov_ned_m2 = a * a.transpose() + Eigen::Matrix3d::Identity();
    p.fix = GnssFixType::kFix3D;
    GnssVelocity v;
    v.header = gps_header(kT0 + std::int64_t{i} * 1'000'000 + 1000, GnssVelocity::kValidVelocity | GnssVelocity::kValidCovariance);
    v.vel_ned_mps = vec(rng, 30);
    const double sh = uniform(rng, 0.05, 0.5), sd = uniform(rng, 0.05, 0.5);
    v.cov_ned_m2ps2 = Eigen::Vector3d(sh * sh, sh * sh, sd * sd).asDiagonal();
    v.fix = GnssFixType::kFix3D;
    const auto out = round_trip({p, v});
    ASSERT_EQ(out.size(), 2u);
    const auto& dp = std::get<GnssPosition>(out[0]);
    EXPECT_EQ(dp.header.time_ns, p.header.time_ns);  // f64 seconds, rounded to whole us
    EXPECT_EQ(dp.header.valid, p.header.valid);
    EXPECT_NEAR(dp.lat_rad, p.lat_rad, 1e-15);
    EXPECT_NEAR(dp.lon_rad, p.lon_rad, 1e-15);
    EXPECT_EQ(dp.height_m, p.height_m);
    EXPECT_LT((dp.cov_ned_m2 - p.cov_ned_m2).cwiseAbs().maxCoeff(), 1e-12);
    const auto& dv = std::get<GnssVelocity>(out[1]);
    EXPECT_EQ(dv.header.time_ns, v.header.time_ns);
    EXPECT_LT((dv.vel_ned_mps - v.vel_ned_mps).norm(), 1e-12);
    EXPECT_LT((dv.cov_ned_m2ps2 - v.cov_ned_m2ps2).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(FeConventions, PoseAnglesAgainstHandDerivedValues) {
  // Vehicle level, nose pointing north-east (heading 45 deg), nose 10 deg up, rolled 5 deg right.
  // FusionEngine (spec §2.7 L640-648): yaw = 90 - 45 = 45 deg, pitch = -10 (positive = nose down),
  // roll = +5 (positive = roll right).
  NavSolution s;
  s.header = gps_header(kT0, NavSolution::kValidAttitude | NavSolution::kValidHeading | NavSolution::kValidVelocity);
  s.mode = NavMode::kAhrs;
  s.rpy_rad = Eigen::Vector3d(5, 10, 45) * kDegToRad;
  s.q_nb = rot::quat_from_rpy(s.rpy_rad);
  // Moving forward at 10 m/s along the body axis: NED velocity from the pitched nose direction.
  s.vel_ned_mps = 10.0 * Eigen::Vector3d(std::cos(10 * kDegToRad) * std::cos(45 * kDegToRad),
                                         std::cos(10 * kDegToRad) * std::sin(45 * kDegToRad),
                                         -std::sin(10 * kDegToRad));
  const PoseMessage p = pose_from(s);
  EXPECT_NEAR(p.ypr_deg[0], 45.0, 1e-9);
  EXPECT_NEAR(p.ypr_deg[1], -10.0, 1e-9);
  EXPECT_NEAR(p.ypr_deg[2], 5.0, 1e-9);
  EXPECT_NEAR(p.velocity_body_mps[0], 10.0, 1e-9);  // forward
  EXPECT_NEAR(p.velocity_body_mps[1], 0.0, 1e-9);   // left
  EXPECT_NEAR(p.velocity_body_mps[2], 0.0, 1e-9);   // up
  // PoseAux: ENU velocity is NED with the horizontal axes swapped and down negated.
  const PoseAuxMessage aux = pose_aux_from(s);
  EXPECT_NEAR(aux.velocity_enu_mps[0], s.vel_ned_mps.y(), 1e-12);
  EXPECT_NEAR(aux.velocity_enu_mps[2], -s.vel_ned_mps.z(), 1e-12);
  // The quaternion rotates the FLU nose (1,0,0) onto the ENU direction (east, north, up) of the nose.
  const Eigen::Quaterniond q(aux.attitude_quaternion[3], aux.attitude_quaternion[0], aux.attitude_quaternion[1],
                             aux.attitude_quaternion[2]);
  const Eigen::Vector3d nose = q * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(nose.x(), std::cos(10 * kDegToRad) * std::sin(45 * kDegToRad), 1e-12);
  EXPECT_NEAR(nose.y(), std::cos(10 * kDegToRad) * std::cos(45 * kDegToRad), 1e-12);
  EXPECT_NEAR(nose.z(), std::sin(10 * kDegToRad), 1e-12);
}

TEST(FeConventions, BodyStdsAreTheNedVariancesTurnedIntoTheBody) {
  // Heading 90 deg (nose east), level: body x = east, y = south, z = down, so the body stds are
  // the east, north and down stds.
  NavSolution s;
  s.header = gps_header(kT0, NavSolution::kValidAttitude | NavSolution::kValidHeading | NavSolution::kValidVelocity |
                                 NavSolution::kValidVelocityStd | NavSolution::kValidPosition |
                                 NavSolution::kValidPositionStd);
  s.mode = NavMode::kNavigation;
  s.rpy_rad = Eigen::Vector3d(0, 0, 90) * kDegToRad;
  s.q_nb = rot::quat_from_rpy(s.rpy_rad);
  s.vel_std_ned_mps = {0.1, 0.2, 0.3};
  s.pos_std_ned_m = {1.0, 2.0, 4.0};
  PoseMessage p = pose_from(s);
  EXPECT_NEAR(p.velocity_std_body_mps[0], 0.2, 1e-6);
  EXPECT_NEAR(p.velocity_std_body_mps[1], 0.1, 1e-6);
  EXPECT_NEAR(p.velocity_std_body_mps[2], 0.3, 1e-6);
  PoseAuxMessage aux = pose_aux_from(s);
  EXPECT_NEAR(aux.position_std_body_m[0], 2.0, 1e-6);
  EXPECT_NEAR(aux.position_std_body_m[1], 1.0, 1e-6);
  EXPECT_NEAR(aux.position_std_body_m[2], 4.0, 1e-6);

  // Any attitude: the diagonal of C_bn diag(s^2) C_nb, formed here as the full product.
  s.rpy_rad = Eigen::Vector3d(-20, 35, 130) * kDegToRad;
  s.q_nb = rot::quat_from_rpy(s.rpy_rad);
  const Eigen::Matrix3d c_bn = s.q_nb.toRotationMatrix().transpose();
  const auto body_std = [&](const Eigen::Vector3d& std_ned) -> Eigen::Vector3d {
    return (c_bn * std_ned.cwiseAbs2().asDiagonal() * c_bn.transpose()).diagonal().cwiseSqrt();
  };
  const Eigen::Vector3d vel_b = body_std(s.vel_std_ned_mps);
  const Eigen::Vector3d pos_b = body_std(s.pos_std_ned_m);
  p = pose_from(s);
  aux = pose_aux_from(s);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(p.velocity_std_body_mps[static_cast<std::size_t>(i)], vel_b(i), 1e-6) << i;
    EXPECT_NEAR(aux.position_std_body_m[static_cast<std::size_t>(i)], pos_b(i), 1e-6) << i;
  }
}

TEST(FeConventions, UndulationFromEgm96OrInvalid) {
  NavSolution s;
  s.header = gps_header(kT0, NavSolution::kValidPosition);
  s.lat_rad = 37.8 * kDegToRad;
  s.lon_rad = -122.4 * kDegToRad;
  const PoseMessage p = pose_from(s);
  const auto n = geo::egm96_undulation_m(s.lat_rad, s.lon_rad);
  if (n) {
    EXPECT_EQ(p.undulation_cm, static_cast<std::int16_t>(std::lround(*n * 100)));
    EXPECT_NEAR(*n, -32.0, 3.0);  // EGM96 near San Francisco is about -32 m
  } else {
    EXPECT_EQ(p.undulation_cm, kInvalidUndulationCm);  // spec L1736
  }
}

}  // namespace
}  // namespace navfuse::frontends::fusionengine

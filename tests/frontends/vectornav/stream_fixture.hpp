// A realistic VN-300 log made by the front-end's own encoder: 200 Hz IMU (delta) and INS
// messages, GNSS1 + GNSS2 position and velocity at 5 Hz, compass heading at 5 Hz and vehicle
// speed echoes at 10 Hz. Shared by the tests, the benchmark and the fuzz seed generator.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/rotation/rotation.hpp"
#include "frontends/vectornav/encoder.hpp"

namespace navfuse::frontends::vectornav::test {

struct StreamContent {
  std::vector<std::uint8_t> bytes;
  std::array<std::size_t, static_cast<std::size_t>(MeasurementKind::kCount)> by_kind{};
  std::size_t frames = 0;  // packets/sentences written (no message here needs split packets)
  std::size_t count(MeasurementKind k) const { return by_kind[static_cast<std::size_t>(k)]; }
};

inline constexpr std::int64_t kStreamT0Ns = 2303LL * 604800 * 1'000'000'000LL + 501342'000'000'000LL;
inline constexpr std::int64_t kImuPeriodNs = 5'000'000;  // 200 Hz
inline constexpr int kGnssEvery = 40;                     // 5 Hz
inline constexpr int kSpeedEvery = 20;                    // 10 Hz

// `with_ascii`: also write the compass heading and vehicle speed sentences.
inline StreamContent make_vn_stream(int epochs, bool with_ascii = true) {
  StreamContent c;
  VnMeasurementEncoder enc;
  auto put = [&](const Measurement& m) {
    if (enc.encode(m, c.bytes)) {
      ++c.by_kind[static_cast<std::size_t>(kind_of(m))];
      ++c.frames;
    }
  };
  for (int i = 0; i < epochs; ++i) {
    const std::int64_t t = kStreamT0Ns + i * kImuPeriodNs;
    const double s = i * 0.005;
    ImuSample imu;
    imu.header = {t, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
    imu.quantity = ImuQuantity::kIncrements;
    imu.dt_s = 0.005;
    imu.gyro = Eigen::Vector3d(0.001 * std::sin(s), 0.002, 0.05 * std::cos(0.1 * s)) * imu.dt_s;
    imu.accel = Eigen::Vector3d(0.3 * std::sin(s), 0.1, -9.80) * imu.dt_s;
    put(imu);
    NavSolution sol;
    sol.header = {t, TimeSource::kGps, 0,
                  NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
                      NavSolution::kValidHeading | NavSolution::kValidPositionStd |
                      NavSolution::kValidVelocityStd | NavSolution::kValidAttitudeStd};
    sol.mode = NavMode::kNavigation;
    sol.gnss_fix = GnssFixType::kFix3D;
    sol.lat_rad = 0.574 + 1e-7 * s;
    sol.lon_rad = -1.688;
    sol.height_m = 163.0;
    sol.vel_ned_mps = {10 * std::cos(0.1 * s), 10 * std::sin(0.1 * s), 0};
    sol.vel_body_mps = {10, 0, 0};
    sol.rpy_rad = {0.01, 0.02, rot::wrap_pi(0.1 * s)};
    sol.q_nb = rot::quat_from_rpy(sol.rpy_rad);
    sol.pos_std_ned_m.setConstant(0.5);
    sol.vel_std_ned_mps.setConstant(0.05);
    sol.att_std_rpy_rad.setConstant(0.005);
    put(sol);
    if (i % kGnssEvery == 0) {
      for (std::uint8_t rx = 0; rx < 2; ++rx) {
        GnssPosition p;
        p.header = {t, TimeSource::kGps, 0,
                    GnssPosition::kValidPosition | GnssPosition::kValidHeight | GnssPosition::kValidCovariance};
        p.receiver_id = rx;
        p.fix = GnssFixType::kSbas;
        p.num_sats = 16;
        p.lat_rad = sol.lat_rad;
        p.lon_rad = sol.lon_rad + rx * 1e-7;
        p.height_m = sol.height_m;
        p.cov_ned_m2 = Eigen::Vector3d(2.0, 2.1, 13.0).asDiagonal();
        put(p);
        GnssVelocity v;
        v.header = {t, TimeSource::kGps, 0, GnssVelocity::kValidVelocity | GnssVelocity::kValidCovariance};
        v.receiver_id = rx;
        v.fix = p.fix;
        v.vel_ned_mps = sol.vel_ned_mps;
        v.cov_ned_m2ps2 = Eigen::Matrix3d::Identity() * 0.03;
        put(v);
      }
      if (with_ascii) {
        GnssHeading h;
        h.header = {t, TimeSource::kGps, 0, GnssHeading::kValidHeading};
        h.heading_rad = sol.rpy_rad.z();
        put(h);
      }
    }
    if (with_ascii && i % kSpeedEvery == 0) {
      VehicleSpeed v;
      v.header = {t, TimeSource::kGps, 0, VehicleSpeed::kValidSpeed};
      v.speed_mps = 10.0;
      put(v);
    }
  }
  return c;
}

}  // namespace navfuse::frontends::vectornav::test

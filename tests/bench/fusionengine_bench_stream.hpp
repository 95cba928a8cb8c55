// The FusionEngine stream of the framing benchmarks: IMUOutput at 100 Hz and Pose at 10 Hz
// (optionally a 30-satellite GNSSSignals message at 1 Hz, as a receiver emits), ~5 MB, repeated
// to `min_bytes` and then `corrupt_fraction` of its bytes XOR-ed with a random non-zero value
// (fixed seed, so every user gets the same bytes). Shared by navfuse_fe_bench, the stream tool
// that writes it to a file for the vendor comparison (fe_bench_stream.cpp) and the vendor
// cross-check test.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "core/rotation/rotation.hpp"
#include "frontends/fusionengine/writer.hpp"
#include "tests/bench/corrupted_stream.hpp"

namespace navfuse::bench {

inline frontends::fusionengine::GnssSignalsMessage fe_bench_signals_message(std::int64_t t) {
  frontends::fusionengine::GnssSignalsMessage m;
  m.p1_time = frontends::fusionengine::Timestamp::from_ns(t);
  m.gps_time = m.p1_time;
  for (std::uint8_t sv = 1; sv <= 30; ++sv) {
    m.satellites.push_back({1, sv, 1, 4500, 18000});
    m.signals.push_back({1, sv, 180, 0x0F});
    m.signals.push_back({2, sv, 160, 0x0F});
  }
  return m;
}

// imu_samples = 40,000 gives the ~5 MB base stream; fewer give a shorter one (tests).
inline std::vector<std::uint8_t> fe_bench_stream(double corrupt_fraction, bool with_signals, std::size_t min_bytes,
                                                 int imu_samples = 40'000) {
  constexpr std::int64_t kT0 = 1'400'000'000'000'000'000;
  frontends::fusionengine::FusionEngineWriter writer;
  std::vector<std::uint8_t> out;
  std::mt19937_64 rng(42);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int i = 0; i < imu_samples; ++i) {
    const std::int64_t t = kT0 + static_cast<std::int64_t>(i) * 10'000'000;
    ImuSample imu;
    imu.header = {t, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
    imu.frame = SensorFrame::kVehicle;
    imu.gyro = {noise(rng), noise(rng), noise(rng)};
    imu.accel = {noise(rng), noise(rng), -9.81 + noise(rng)};
    frontends::fusionengine::ImuOutputMessage m;
    frontends::fusionengine::imu_output_from(imu, m);
    writer.append(m, out);
    if (with_signals && i % 100 == 0) writer.append(fe_bench_signals_message(t), out);
    if (i % 10 == 0) {
      NavSolution s;
      s.header = {t, TimeSource::kGps, 0,
                  NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
                      NavSolution::kValidHeading | NavSolution::kValidPositionStd | NavSolution::kValidUndulation};
      s.mode = NavMode::kNavigation;
      s.gnss_fix = GnssFixType::kRtkFixed;
      s.lat_rad = 0.66 + 1e-8 * i;
      s.lon_rad = -2.13;
      s.height_m = 30.0;
      s.undulation_m = -32.0;
      s.vel_ned_mps = {10.0, 1.0, 0.0};
      s.q_nb = rot::quat_from_rpy({0.01, 0.02, 0.1 * i});
      s.pos_std_ned_m = {0.02, 0.02, 0.05};
      writer.append(frontends::fusionengine::pose_from(s), out);
    }
  }
  repeat_to(out, min_bytes);
  const auto n_corrupt = static_cast<std::size_t>(corrupt_fraction * static_cast<double>(out.size()));
  for (std::size_t k = 0; k < n_corrupt; ++k) {
    out[rng() % out.size()] ^= static_cast<std::uint8_t>(1 + rng() % 255);
  }
  return out;
}

}  // namespace navfuse::bench

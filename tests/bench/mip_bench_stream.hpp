// The MIP stream of the framing benchmarks: a CV7-style stream of 0x80 IMU packets (GPS
// timestamp, scaled accel and gyro) at 10x the rate of 0x82 filter packets (timestamp, status,
// LLH, velocity, quaternion, Euler, uncertainties), as MicroStrain's mip_sdk framing benchmark
// uses, ~8 MB, repeated to `min_bytes`; then each byte is, with a chance of `corrupt_percent` in
// 100, replaced by a random value (fixed seed, so every user gets the same bytes). Shared by
// navfuse_mip_bench and the stream tool that writes it to a file for the vendor comparison
// (mip_bench_stream.cpp, mip_vendor_compare.sh).
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "core/time/gps_time.hpp"
#include "frontends/mip/encoder.hpp"
#include "tests/bench/corrupted_stream.hpp"

namespace navfuse::bench {

inline std::vector<std::uint8_t> mip_bench_stream(int corrupt_percent, std::size_t min_bytes) {
  frontends::mip::MipEncoder enc;
  std::vector<std::uint8_t> bytes;
  const std::int64_t t0 = time::gps_ns_from_week_tow(2350, 1000.0);
  for (int i = 0; bytes.size() < (8u << 20); ++i) {
    MeasurementHeader h;
    h.time_ns = t0 + i * 1'000'000LL;
    h.time_source = TimeSource::kGps;
    ImuSample imu;
    imu.header = h;
    imu.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
    imu.gyro = {0.001 * i, 0.002, -0.003};
    imu.accel = {0.1, -0.2, -9.81};
    enc.encode(imu, bytes);
    if (i % 10 == 0) {
      NavSolution s;
      s.header = h;
      s.header.valid = NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
                       NavSolution::kValidPositionStd | NavSolution::kValidVelocityStd | NavSolution::kValidAttitudeStd;
      s.mode = NavMode::kNavigation;
      s.lat_rad = 0.7;
      s.lon_rad = -2.1;
      enc.encode(s, bytes);
    }
  }
  repeat_to(bytes, min_bytes);
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> pct(0, 99), byte(0, 255);
  for (auto& b : bytes)
    if (pct(rng) < corrupt_percent) b = static_cast<std::uint8_t>(byte(rng));
  return bytes;
}

}  // namespace navfuse::bench

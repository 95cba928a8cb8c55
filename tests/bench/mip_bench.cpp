// Throughput of the MIP front-end on a CV7-style stream: 0x80 IMU packets (GPS timestamp, scaled
// accel and gyro) at 10x the rate of 0x82 filter packets (timestamp, status, LLH, velocity,
// quaternion, Euler, uncertainties), as MicroStrain's mip_sdk framing benchmark uses, repeated to
// 200 MB (corrupted_stream.hpp); 1% of the bytes are replaced by random values (fixed seed). Reports bytes_per_second for framing alone
// and for framing plus decoding into core measurements.
#include <benchmark/benchmark.h>

#include <random>

#include "core/time/gps_time.hpp"
#include "frontends/mip/decoder.hpp"
#include "frontends/mip/encoder.hpp"
#include "frontends/mip/framer.hpp"
#include "tests/bench/corrupted_stream.hpp"

namespace {

using namespace navfuse;
using namespace navfuse::frontends;

std::vector<std::uint8_t> make_stream() {
  mip::MipEncoder enc;
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
  bench::repeat_to(bytes, bench::kCorruptedStreamBytes);
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> pct(0, 99), byte(0, 255);
  for (auto& b : bytes)
    if (pct(rng) == 0) b = static_cast<std::uint8_t>(byte(rng));
  return bytes;
}

const std::vector<std::uint8_t>& stream() {
  static const auto s = make_stream();
  return s;
}

constexpr std::size_t kChunk = 4096;  // a typical read() size

void BM_MipFraming(benchmark::State& state) {
  const auto& s = stream();
  std::uint64_t frames = 0;
  for (auto _ : state) {
    mip::Framer f;
    for (std::size_t pos = 0; pos < s.size(); pos += kChunk) {
      const std::size_t n = std::min(kChunk, s.size() - pos);
      f.feed(std::span<const std::uint8_t>(s).subspan(pos, n), [&](const mip::PacketView& p) {
        benchmark::DoNotOptimize(p.payload.data());
      });
    }
    f.finish([](const mip::PacketView&) {});
    frames = f.counters().frames;
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * s.size()));
  state.counters["frames"] = static_cast<double>(frames);
}
BENCHMARK(BM_MipFraming)->Unit(benchmark::kMillisecond);

struct CountingSink : DecodeSink {
  std::uint64_t n = 0;
  void on_measurement(const Measurement& m) override {
    ++n;
    benchmark::DoNotOptimize(&m);
  }
};

void BM_MipFramingAndDecoding(benchmark::State& state) {
  const auto& s = stream();
  std::uint64_t measurements = 0;
  for (auto _ : state) {
    mip::MipDecoder dec;
    CountingSink sink;
    for (std::size_t pos = 0; pos < s.size(); pos += kChunk) {
      const std::size_t n = std::min(kChunk, s.size() - pos);
      dec.feed(std::span<const std::uint8_t>(s).subspan(pos, n), sink);
    }
    dec.finish(sink);
    measurements = sink.n;
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * s.size()));
  state.counters["measurements"] = static_cast<double>(measurements);
}
BENCHMARK(BM_MipFramingAndDecoding)->Unit(benchmark::kMillisecond);

}  // namespace

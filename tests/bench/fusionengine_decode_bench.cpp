// Framing + decoding of a FusionEngine stream of IMUOutput (100 Hz) and Pose (10 Hz) messages
// with 1 % of its bytes corrupted at random (fixed seed), through the StreamDecoder into a
// sink that only counts; the corrupted stream is repeated to 200 MB first (corrupted_stream.hpp). Reports bytes_per_second; the goal is >= 1 GB/s on one core.
// The "WithSignals" variant adds a GNSSSignals message (30 satellites, 60 signals) at 1 Hz, as a
// receiver emits: a corrupted size byte in a variable-length header is what the per-type bounds
// (payload_bound.hpp) cap, where the frame limit let it claim up to 16 MiB (issue 15.11).
#include <benchmark/benchmark.h>

#include <random>

#include "core/rotation/rotation.hpp"
#include "tests/bench/corrupted_stream.hpp"
#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/writer.hpp"

namespace {

using namespace navfuse;

class CountingSink final : public frontends::DecodeSink {
 public:
  void on_measurement(const Measurement&) override { ++measurements; }
  std::uint64_t measurements = 0;
};

frontends::fusionengine::GnssSignalsMessage signals_message(std::int64_t t) {
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

std::vector<std::uint8_t> make_stream(double corrupt_fraction, bool with_signals = false) {
  constexpr std::int64_t kT0 = 1'400'000'000'000'000'000;
  constexpr int kImuSamples = 40'000;  // ~5 MB
  frontends::fusionengine::FusionEngineWriter writer;
  std::vector<std::uint8_t> out;
  std::mt19937_64 rng(42);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int i = 0; i < kImuSamples; ++i) {
    const std::int64_t t = kT0 + static_cast<std::int64_t>(i) * 10'000'000;
    ImuSample imu;
    imu.header = {t, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
    imu.frame = SensorFrame::kVehicle;
    imu.gyro = {noise(rng), noise(rng), noise(rng)};
    imu.accel = {noise(rng), noise(rng), -9.81 + noise(rng)};
    frontends::fusionengine::ImuOutputMessage m;
    frontends::fusionengine::imu_output_from(imu, m);
    writer.append(m, out);
    if (with_signals && i % 100 == 0) writer.append(signals_message(t), out);
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
  if (corrupt_fraction > 0.0) bench::repeat_to(out, bench::kCorruptedStreamBytes);
  const auto n_corrupt = static_cast<std::size_t>(corrupt_fraction * static_cast<double>(out.size()));
  for (std::size_t k = 0; k < n_corrupt; ++k) {
    out[rng() % out.size()] ^= static_cast<std::uint8_t>(1 + rng() % 255);
  }
  return out;
}

void BM_FeDecodeCorrupted(benchmark::State& state, bool with_signals) {
  const std::vector<std::uint8_t> stream = make_stream(0.01, with_signals);
  std::uint64_t frames = 0, bad = 0, measurements = 0;
  for (auto _ : state) {
    frontends::fusionengine::FusionEngineDecoder decoder;
    CountingSink sink;
    decoder.feed(stream, sink);
    decoder.finish(sink);
    benchmark::DoNotOptimize(sink.measurements);
    frames = decoder.counters().frames;
    bad = decoder.counters().bad_frames;
    measurements = sink.measurements;
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * stream.size()));
  state.counters["frames"] = static_cast<double>(frames);
  state.counters["bad_frames"] = static_cast<double>(bad);
  state.counters["measurements"] = static_cast<double>(measurements);
}
BENCHMARK_CAPTURE(BM_FeDecodeCorrupted, ImuPose, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FeDecodeCorrupted, WithSignals, true)->Unit(benchmark::kMillisecond);

void BM_FeDecodeClean(benchmark::State& state) {
  const std::vector<std::uint8_t> stream = make_stream(0.0);
  for (auto _ : state) {
    frontends::fusionengine::FusionEngineDecoder decoder;
    CountingSink sink;
    decoder.feed(stream, sink);
    decoder.finish(sink);
    benchmark::DoNotOptimize(sink.measurements);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * stream.size()));
}
BENCHMARK(BM_FeDecodeClean)->Unit(benchmark::kMillisecond);

}  // namespace

// Framing + decoding of a FusionEngine stream of IMUOutput (100 Hz) and Pose (10 Hz) messages
// with 1 % of its bytes corrupted at random (fixed seed), through the StreamDecoder into a
// sink that only counts; the corrupted stream is repeated to 200 MB first (the stream:
// fusionengine_bench_stream.hpp). Reports bytes_per_second; the goal is >= 1 GB/s on one
// core. tests/bench/fe_vendor_compare.sh times Point One's own parser on the same bytes.
// The "WithSignals" variant adds a GNSSSignals message (30 satellites, 60 signals) at 1 Hz, as a
// receiver emits: a corrupted size byte in a variable-length header is what the per-type bounds
// (payload_bound.hpp) cap, where the frame limit let it claim up to 16 MiB (issue 15.11).
#include <benchmark/benchmark.h>

#include "frontends/fusionengine/decoder.hpp"
#include "tests/bench/fusionengine_bench_stream.hpp"

namespace {

using namespace navfuse;

class CountingSink final : public frontends::DecodeSink {
 public:
  void on_measurement(const Measurement&) override { ++measurements; }
  std::uint64_t measurements = 0;
};

void BM_FeDecodeCorrupted(benchmark::State& state, bool with_signals) {
  const std::vector<std::uint8_t> stream = bench::fe_bench_stream(0.01, with_signals, bench::kCorruptedStreamBytes);
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
  const std::vector<std::uint8_t> stream = bench::fe_bench_stream(0.0, false, 0);
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

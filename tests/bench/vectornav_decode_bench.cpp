// Framing + decoding throughput of the "vn" StreamDecoder (issue #5 goal: >= 500 MB/s) on the
// log the encoder writes for fusion: 200 Hz IMU (delta) and INS messages interleaved with 5 Hz
// GNSS1/GNSS2 position and velocity messages, repeated to 200 MB (corrupted_stream.hpp), with 1% of the bytes replaced by random values
// (fixed seed), fed in 64 KiB chunks as a file reader would.
#include <benchmark/benchmark.h>

#include <random>

#include "frontends/vectornav/decoder.hpp"
#include "tests/bench/corrupted_stream.hpp"
#include "tests/frontends/vectornav/stream_fixture.hpp"

namespace {

using navfuse::Measurement;
using navfuse::frontends::DecodeSink;
using navfuse::frontends::vectornav::VnStreamDecoder;

constexpr int kEpochs = 60 * 200;           // one minute of log
constexpr double kCorruptedFraction = 0.01;
constexpr std::size_t kChunkBytes = 64 * 1024;
constexpr std::uint64_t kSeed = 0x5EED;

struct CountingSink : DecodeSink {
  std::size_t n = 0;
  void on_measurement(const Measurement&) override { ++n; }
};

const std::vector<std::uint8_t>& corrupted_log() {
  static const std::vector<std::uint8_t> log = [] {
    std::vector<std::uint8_t> bytes = navfuse::frontends::vectornav::test::make_vn_stream(kEpochs, false).bytes;
    navfuse::bench::repeat_to(bytes, navfuse::bench::kCorruptedStreamBytes);
    std::mt19937_64 rng(kSeed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (auto& b : bytes)
      if (u(rng) < kCorruptedFraction) b = static_cast<std::uint8_t>(rng());
    return bytes;
  }();
  return log;
}

void BM_VnDecodeCorruptedLog(benchmark::State& state) {
  const auto& log = corrupted_log();
  std::size_t measurements = 0;
  for (auto _ : state) {
    VnStreamDecoder decoder;
    CountingSink sink;
    for (std::size_t at = 0; at < log.size(); at += kChunkBytes)
      decoder.feed(std::span(log).subspan(at, std::min(kChunkBytes, log.size() - at)), sink);
    decoder.finish(sink);
    measurements = sink.n;
    benchmark::DoNotOptimize(decoder.counters().frames);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * log.size()));
  state.counters["log_bytes"] = static_cast<double>(log.size());
  state.counters["measurements"] = static_cast<double>(measurements);
}
BENCHMARK(BM_VnDecodeCorruptedLog)->Unit(benchmark::kMillisecond);

}  // namespace

// Throughput of the MIP front-end on the CV7-style stream of mip_bench_stream.hpp, repeated to
// 200 MB (corrupted_stream.hpp) with 1% of the bytes replaced by random values. Reports
// bytes_per_second for framing alone and for framing plus decoding into core measurements.
#include <benchmark/benchmark.h>

#include "frontends/mip/decoder.hpp"
#include "frontends/mip/framer.hpp"
#include "tests/bench/mip_bench_stream.hpp"

namespace {

using namespace navfuse;
using namespace navfuse::frontends;

const std::vector<std::uint8_t>& stream() {
  static const auto s = bench::mip_bench_stream(1, bench::kCorruptedStreamBytes);
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

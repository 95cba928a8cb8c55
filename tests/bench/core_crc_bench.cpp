// CRC-32 as the FusionEngine writer and framer use it: the slicing-by-8 tables against carry-less
// multiplication (core/bytes/crc32_kernels.hpp), on buffers the size of a Pose frame's CRC span
// (~150 bytes), of an IMUOutput frame (~60 bytes) and on 64 kB. Reports bytes_per_second; the
// micro goal is the carry-less kernel at >= 2x the tables' rate on Pose-sized buffers.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "core/bytes/crc32_kernels.hpp"

namespace {

using navfuse::bytes::detail::crc32_clmul;
using navfuse::bytes::detail::crc32_clmul_available;
using navfuse::bytes::detail::crc32_slice8;

std::vector<std::uint8_t> bytes_of(std::size_t n) {
  std::vector<std::uint8_t> v(n);
  std::uint32_t x = 1;
  for (auto& b : v) {
    x = x * 1664525u + 1013904223u;
    b = static_cast<std::uint8_t>(x >> 24);
  }
  return v;
}

template <std::uint32_t (*Kernel)(std::span<const std::uint8_t>, std::uint32_t)>
void BM_Crc32(benchmark::State& state) {
  if (Kernel == &crc32_clmul && !crc32_clmul_available()) {
    state.SkipWithError("no PCLMULQDQ on this CPU");
    return;
  }
  const std::vector<std::uint8_t> data = bytes_of(static_cast<std::size_t>(state.range(0)));
  std::uint32_t reg = 0xFFFFFFFFu;
  for (auto _ : state) {
    reg = Kernel(data, reg);
    benchmark::DoNotOptimize(reg);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}

BENCHMARK_TEMPLATE(BM_Crc32, crc32_slice8)->Arg(60)->Arg(150)->Arg(64 * 1024);
BENCHMARK_TEMPLATE(BM_Crc32, crc32_clmul)->Arg(60)->Arg(150)->Arg(64 * 1024);

}  // namespace

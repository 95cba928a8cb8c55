// MIP Fletcher checksum in a form the compiler vectorises, for the framer's hot path.
//
// The spec's loop (L4070-4089, core/bytes mip_fletcher) is a serial chain of two 8-bit sums:
// after n bytes, sum1 = sum(b_i) and sum2 = sum((n - i) * b_i) for i = 0..n-1, both mod 256.
// Written as the closed form with 32-bit accumulators the loop has no carried dependency, which
// lets GCC/Clang use SIMD; the framer checks every byte of every packet, so this bounds framing
// speed. Equality with core mip_fletcher is a unit test (tests/frontends/mip/framer_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace navfuse::frontends::mip {

inline std::uint16_t fletcher_fast(const std::uint8_t* data, std::size_t n) {
  std::uint32_t sum1 = 0;
  std::uint32_t sum2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sum1 += data[i];
    sum2 += static_cast<std::uint32_t>(n - i) * data[i];
  }
  return static_cast<std::uint16_t>(((sum1 & 0xFFu) << 8) | (sum2 & 0xFFu));
}

}  // namespace navfuse::frontends::mip

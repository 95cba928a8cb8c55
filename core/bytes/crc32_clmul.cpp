// CRC-32 by carry-less multiplication: the folding method of Gopal et al., "Fast CRC Computation
// for Generic Polynomials Using PCLMULQDQ Instruction" (Intel white paper, 2009), for the
// reflected polynomial 0xEDB88320. A replay writing a FusionEngine frame per IMU sample spends
// most of its CRC time here instead of in table lookups (tests/bench/core_crc_bench.cpp).
//
// Folding: the message is M = A x^D + B (mod P) with A, B 128-bit blocks D bits apart. Splitting
// A into its high-degree half H and low-degree half L (64 bits each),
//   A x^D = H x^(D+64) + L x^D == H (x^(D+32) mod P) x^32 + L (x^(D-32) mod P) x^32,
// and each product of a 64-bit half with a 33-bit constant fits the 128 bits of B. In the
// reflected bit order a register bit i stands for x^(127-i); one PCLMULQDQ of a reflected half
// and a constant whose bit j stands for x^(32-j) yields exactly the "x^32" factor above, so the
// constants are reflect32(x^n mod P) << 1 (computed below, not transcribed).
//
// The 128 bits left after folding are reduced by the table loop (16 bytes): its register after
// bytes R from a zero start is R x^32 mod P, which is what the CRC of the folded value is.
#include "core/bytes/crc32_kernels.hpp"

#include "core/cpu/cpu_features.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace navfuse::bytes::detail {
namespace {

// x^n mod P in the normal bit order (bit k is the coefficient of x^k), P = 0x104C11DB7.
constexpr std::uint32_t x_pow_mod_p(unsigned n) {
  std::uint32_t r = 1;
  for (unsigned i = 0; i < n; ++i) r = (r & 0x80000000u) ? (r << 1) ^ 0x04C11DB7u : r << 1;
  return r;
}
constexpr std::uint32_t reflect32(std::uint32_t v) {
  std::uint32_t r = 0;
  for (int i = 0; i < 32; ++i) r |= ((v >> i) & 1u) << (31 - i);
  return r;
}
// The folding constant for x^n (see the file comment).
constexpr std::uint64_t fold_constant(unsigned n) { return static_cast<std::uint64_t>(reflect32(x_pow_mod_p(n))) << 1; }

// Fold distances: four 128-bit lanes 512 bits apart, then one lane 128 bits at a time.
constexpr std::uint64_t kFold512High = fold_constant(512 + 32), kFold512Low = fold_constant(512 - 32);
constexpr std::uint64_t kFold128High = fold_constant(128 + 32), kFold128Low = fold_constant(128 - 32);

}  // namespace

#if defined(__x86_64__)

namespace {

// A lane folded D bits forward and added to the block there; `k` holds {x^(D+32), x^(D-32)}
// constants for the lane's {low (high-degree), high (low-degree)} qwords.
__attribute__((target("pclmul,sse2"))) inline __m128i fold(__m128i lane, __m128i k, __m128i next) {
  const __m128i hi = _mm_clmulepi64_si128(lane, k, 0x00);
  const __m128i lo = _mm_clmulepi64_si128(lane, k, 0x11);
  return _mm_xor_si128(_mm_xor_si128(hi, lo), next);
}

__attribute__((target("pclmul,sse2"))) inline __m128i load(const std::uint8_t* p) {
  return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
}

}  // namespace

__attribute__((target("pclmul,sse2"))) std::uint32_t crc32_clmul(std::span<const std::uint8_t> data, std::uint32_t reg) {
  const std::uint8_t* p = data.data();
  std::size_t n = data.size();
  if (n < 32) return crc32_slice8(data, reg);  // nothing to fold

  // The register enters through the first 32 message bits (the CRC is linear in both).
  __m128i x = _mm_xor_si128(load(p), _mm_cvtsi32_si128(static_cast<int>(reg)));
  const __m128i k128 = _mm_set_epi64x(static_cast<long long>(kFold128Low), static_cast<long long>(kFold128High));
  if (n >= 128) {
    // Four independent lanes hide the multiplier's latency; they are folded into one at the end.
    __m128i x1 = load(p + 16), x2 = load(p + 32), x3 = load(p + 48);
    p += 64;
    n -= 64;
    const __m128i k512 = _mm_set_epi64x(static_cast<long long>(kFold512Low), static_cast<long long>(kFold512High));
    while (n >= 64) {
      x = fold(x, k512, load(p));
      x1 = fold(x1, k512, load(p + 16));
      x2 = fold(x2, k512, load(p + 32));
      x3 = fold(x3, k512, load(p + 48));
      p += 64;
      n -= 64;
    }
    x = fold(fold(fold(x, k128, x1), k128, x2), k128, x3);
  } else {
    p += 16;
    n -= 16;
  }
  while (n >= 16) {
    x = fold(x, k128, load(p));
    p += 16;
    n -= 16;
  }
  alignas(16) std::uint8_t folded[16];
  _mm_store_si128(reinterpret_cast<__m128i*>(folded), x);
  return crc32_slice8({p, n}, crc32_slice8(folded, 0));
}

bool crc32_clmul_available() { return cpu::has_pclmul(); }

#else

std::uint32_t crc32_clmul(std::span<const std::uint8_t> data, std::uint32_t reg) { return crc32_slice8(data, reg); }
bool crc32_clmul_available() { return false; }

#endif

}  // namespace navfuse::bytes::detail

// The two CRC-32 (IEEE 802.3, reflected) implementations behind bytes::crc32 (checks.hpp), named
// so that tests and benchmarks can compare them on the same input. Both take and return the
// raw register (no initial or final inversion): crc32() does the inversions once.
#pragma once

#include <cstdint>
#include <span>

namespace navfuse::bytes::detail {

// Slicing-by-8 tables: portable, ~1 cycle per byte.
std::uint32_t crc32_slice8(std::span<const std::uint8_t> data, std::uint32_t reg);

// Carry-less multiplication (x86-64 PCLMULQDQ), folding 64 bytes per step. Call only when
// crc32_clmul_available(); on other targets it is the slicing-by-8 loop.
std::uint32_t crc32_clmul(std::span<const std::uint8_t> data, std::uint32_t reg);

// Whether this CPU has PCLMULQDQ (checked once, at first use).
bool crc32_clmul_available();

}  // namespace navfuse::bytes::detail

#include "core/bytes/checks.hpp"

#include <array>

#include "core/bytes/crc32_kernels.hpp"

namespace navfuse::bytes {
namespace {

// Slicing-by-8 tables for CRC-32: the FusionEngine framer checks every byte of every frame,
// so the table-driven bytewise loop (~1 byte/cycle) would cap framing speed.
struct Crc32Tables {
  std::array<std::array<std::uint32_t, 256>, 8> t{};
  constexpr Crc32Tables() {
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? (0xEDB88320u ^ (c >> 1)) : (c >> 1);
      t[0][i] = c;
    }
    for (std::uint32_t i = 0; i < 256; ++i)
      for (std::size_t s = 1; s < 8; ++s) t[s][i] = (t[s - 1][i] >> 8) ^ t[0][t[s - 1][i] & 0xFFu];
  }
};
constexpr Crc32Tables kCrc32{};

// Slicing-by-8 tables for CRC-16/XMODEM (MSB first): t[k][v] is the CRC of byte v followed by k
// zero bytes, so eight bytes fold in with eight independent lookups. The VectorNav framer
// checks every candidate packet, and the bytewise loop (~2 cycles/byte) capped its speed.
struct Crc16Tables {
  std::array<std::array<std::uint16_t, 256>, 8> t{};
  constexpr Crc16Tables() {
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint16_t c = static_cast<std::uint16_t>(i << 8);
      for (int k = 0; k < 8; ++k)
        c = (c & 0x8000u) ? static_cast<std::uint16_t>((c << 1) ^ 0x1021u) : static_cast<std::uint16_t>(c << 1);
      t[0][i] = c;
    }
    for (std::uint32_t i = 0; i < 256; ++i)
      for (std::size_t s = 1; s < 8; ++s)
        t[s][i] = static_cast<std::uint16_t>((t[s - 1][i] << 8) ^ t[0][t[s - 1][i] >> 8]);
  }
};
constexpr Crc16Tables kCrc16{};

}  // namespace

namespace detail {

std::uint32_t crc32_slice8(std::span<const std::uint8_t> data, std::uint32_t reg) {
  std::uint32_t c = reg;
  const std::uint8_t* p = data.data();
  std::size_t n = data.size();
  const auto& t = kCrc32.t;
  while (n >= 8) {
    const std::uint32_t lo = c ^ (static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                                  static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24);
    c = t[7][lo & 0xFF] ^ t[6][(lo >> 8) & 0xFF] ^ t[5][(lo >> 16) & 0xFF] ^ t[4][lo >> 24] ^
        t[3][p[4]] ^ t[2][p[5]] ^ t[1][p[6]] ^ t[0][p[7]];
    p += 8;
    n -= 8;
  }
  while (n--) c = t[0][(c ^ *p++) & 0xFFu] ^ (c >> 8);
  return c;
}

}  // namespace detail

std::uint32_t crc32(std::span<const std::uint8_t> data, std::uint32_t previous) {
  // Carry-less multiplication where the CPU has it (twice the tables' rate on 150-byte frames,
  // six times on long buffers: tests/bench/core_crc_bench.cpp), the tables elsewhere.
  if (detail::crc32_clmul_available()) return ~detail::crc32_clmul(data, ~previous);
  return ~detail::crc32_slice8(data, ~previous);
}

std::uint16_t crc16_xmodem(std::span<const std::uint8_t> data, std::uint16_t init) {
  std::uint16_t c = init;
  const std::uint8_t* p = data.data();
  std::size_t n = data.size();
  const auto& t = kCrc16.t;
  while (n >= 8) {
    // The running CRC enters through the first two bytes (the CRC is linear in its input).
    c = static_cast<std::uint16_t>(t[7][p[0] ^ (c >> 8)] ^ t[6][p[1] ^ (c & 0xFFu)] ^ t[5][p[2]] ^ t[4][p[3]] ^
                                   t[3][p[4]] ^ t[2][p[5]] ^ t[1][p[6]] ^ t[0][p[7]]);
    p += 8;
    n -= 8;
  }
  while (n--) c = static_cast<std::uint16_t>((c << 8) ^ t[0][((c >> 8) ^ *p++) & 0xFFu]);
  return c;
}

std::uint16_t mip_fletcher(std::span<const std::uint8_t> data) {
  std::uint8_t sum1 = 0, sum2 = 0;
  for (std::uint8_t b : data) {
    sum1 = static_cast<std::uint8_t>(sum1 + b);
    sum2 = static_cast<std::uint8_t>(sum2 + sum1);
  }
  return static_cast<std::uint16_t>((sum1 << 8) | sum2);
}

std::uint8_t nmea_xor(std::span<const std::uint8_t> data) {
  std::uint8_t x = 0;
  for (std::uint8_t b : data) x ^= b;
  return x;
}

}  // namespace navfuse::bytes

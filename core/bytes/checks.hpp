// The integrity checks of the four protocols navfuse speaks.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace navfuse::bytes {

// CRC-32 (IEEE 802.3, reflected, poly 0xEDB88320, init and xorout 0xFFFFFFFF) as FusionEngine
// uses it (FusionEngine spec §2.4). Check value: crc32("123456789") = 0xCBF43926.
// `previous` chains calls: crc32(b, crc32(a)) == crc32(a ++ b).
std::uint32_t crc32(std::span<const std::uint8_t> data, std::uint32_t previous = 0);

// CRC-16/XMODEM (poly 0x1021, init 0, no reflection) as VectorNav's "16-bit CRC" (VN-300 ICD
// §1.3 L620-641). Check value: 0x31C3. Running the CRC over a message including its trailing
// big-endian CRC yields 0.
std::uint16_t crc16_xmodem(std::span<const std::uint8_t> data, std::uint16_t init = 0);

// MIP 16-bit Fletcher-style checksum over sync bytes, header and payload (MIP spec L4070-4089):
// two running 8-bit sums wrapping mod 256 (not the mod-255 Fletcher-16); returned as
// (sum1 << 8) | sum2, transmitted big-endian.
std::uint16_t mip_fletcher(std::span<const std::uint8_t> data);

// NMEA XOR of every character between '$' and '*' (exclusive), as NMEA 0183, VectorNav ASCII
// and Unicore sentences use it.
std::uint8_t nmea_xor(std::span<const std::uint8_t> data);
inline std::uint8_t nmea_xor(std::string_view s) {
  return nmea_xor(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(s.data()), s.size()));
}

inline std::span<const std::uint8_t> as_bytes(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

}  // namespace navfuse::bytes

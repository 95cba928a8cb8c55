// The four protocols' integrity checks against their catalogued check values (Greg Cook's CRC
// catalogue: CRC-32/ISO-HDLC check 0xCBF43926, CRC-16/XMODEM check 0x31C3) and against packets
// printed in the vendor documents (digests in ../shared/reference/).
#include "core/bytes/checks.hpp"

#include "core/bytes/crc32_kernels.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace navfuse::bytes {
namespace {

std::vector<std::uint8_t> hex(const std::string& text) {
  std::vector<std::uint8_t> out;
  std::string digits;
  for (char c : text) if (std::isxdigit(static_cast<unsigned char>(c))) digits += c;
  for (std::size_t i = 0; i + 1 < digits.size(); i += 2) out.push_back(static_cast<std::uint8_t>(std::stoi(digits.substr(i, 2), nullptr, 16)));
  return out;
}

TEST(Crc32, CatalogueCheckValue) { EXPECT_EQ(crc32(as_bytes("123456789")), 0xCBF43926u); }

TEST(Crc32, EmptyIsZero) { EXPECT_EQ(crc32({}), 0u); }

TEST(Crc32, ChainingEqualsOneShotForEverySplit) {
  std::vector<std::uint8_t> data(100);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 37 + 11);
  const std::uint32_t whole = crc32(data);
  for (std::size_t split = 0; split <= data.size(); ++split) {
    const std::span<const std::uint8_t> s(data);
    EXPECT_EQ(crc32(s.subspan(split), crc32(s.first(split))), whole) << split;
  }
}

TEST(Crc32, LongBuffersMatchAnIndependentImplementation) {
  // Values from Python's zlib.crc32 (zlib's own tables), for buffers long enough to take the
  // carry-less-multiplication path (>= 64 bytes) on CPUs that have it.
  std::vector<std::uint8_t> ramp(256);
  for (std::size_t i = 0; i < ramp.size(); ++i) ramp[i] = static_cast<std::uint8_t>(i);
  EXPECT_EQ(crc32(ramp), 0x29058C73u);
  std::string digits;
  for (int i = 0; i < 100; ++i) digits += "123456789";
  EXPECT_EQ(crc32(as_bytes(digits)), 0x09FD0FD7u);
  std::vector<std::uint8_t> mixed(1000);
  for (std::size_t i = 0; i < mixed.size(); ++i) mixed[i] = static_cast<std::uint8_t>(i * 37 + 11);
  EXPECT_EQ(crc32(mixed), 0xC3905A1Du);
  EXPECT_EQ(crc32(std::vector<std::uint8_t>(4096, 0xFF)), 0xF154670Au);
}

TEST(Crc32, CarrylessMultiplyEqualsTablesForEveryLengthAndAlignment) {
  if (!detail::crc32_clmul_available()) GTEST_SKIP() << "no PCLMULQDQ on this CPU";
  std::vector<std::uint8_t> data(1100);
  std::uint32_t x = 12345;
  for (auto& b : data) {
    x = x * 1103515245u + 12345u;  // any bytes will do; a fixed LCG keeps the test repeatable
    b = static_cast<std::uint8_t>(x >> 23);
  }
  const std::span<const std::uint8_t> all(data);
  for (std::size_t offset = 0; offset < 16; ++offset) {
    for (std::size_t n = 0; offset + n <= data.size(); n += (n < 300 ? 1 : 37)) {
      const auto s = all.subspan(offset, n);
      for (std::uint32_t reg : {0u, 0xFFFFFFFFu, 0x1234ABCDu}) {
        ASSERT_EQ(detail::crc32_clmul(s, reg), detail::crc32_slice8(s, reg)) << offset << " " << n << " " << reg;
      }
    }
  }
}

TEST(Crc16Xmodem, CatalogueCheckValue) { EXPECT_EQ(crc16_xmodem(as_bytes("123456789")), 0x31C3u); }

TEST(Crc16Xmodem, VectorNavAsciiCrcTable) {
  // VN-300 digest §2.3: CRC16 of the text between '$' and '*', computed there with a bitwise
  // 0x1021 implementation independent of ours.
  EXPECT_EQ(crc16_xmodem(as_bytes("VNRRG,5")), 0xD5A3u);
  EXPECT_EQ(crc16_xmodem(as_bytes("VNRRG,11")), 0xD26Eu);
  EXPECT_EQ(crc16_xmodem(as_bytes("VNWNV")), 0xDBDFu);
  EXPECT_EQ(crc16_xmodem(as_bytes("VNYPR,+010.071,+000.278,-002.026")), 0x29F8u);
}

TEST(Crc16Xmodem, MessageWithItsCrcChecksToZero) {
  // The ICD's receiver check (L583-589): CRC over payload plus big-endian CRC is zero.
  const std::string payload = "VNRRG,08,-177.483,+000.594,+004.534";
  const std::uint16_t c = crc16_xmodem(as_bytes(payload));
  EXPECT_EQ(c, 0x6CC8u);
  std::vector<std::uint8_t> with_crc(payload.begin(), payload.end());
  with_crc.push_back(static_cast<std::uint8_t>(c >> 8));
  with_crc.push_back(static_cast<std::uint8_t>(c & 0xFF));
  EXPECT_EQ(crc16_xmodem(with_crc), 0u);
}

TEST(MipFletcher, PrintedPacketsVerify) {
  // MIP digest §11.1 (doc L3901, L3913, L3921): the last two bytes are the checksum of the rest.
  for (const char* packet : {"75650102 0201 E0C6", "75 65 01 04 04 F1 01 00 D5 6A",
                             "75650C09 04F10E00 058E8003E8 F058",
                             "75 65 80 0E 0E 06 3E7A63A0 BB8E3B29 7FE5BF7F 86 08"}) {
    const auto p = hex(packet);
    const std::uint16_t expected = static_cast<std::uint16_t>(p[p.size() - 2] << 8 | p.back());
    EXPECT_EQ(mip_fletcher(std::span(p).first(p.size() - 2)), expected) << packet;
  }
}

TEST(MipFletcher, DocumentErratumDetected) {
  // Digest §11.1, doc L3846: printed checksum E0C6 is wrong; the correct one is B11E.
  const auto p = hex("75 65 80 1C 0E 05 3E7A63A0 BB8E3B29 7FE5BF7F 0E 06 3E7A63A0 BB8E3B29 7FE5BF7F");
  EXPECT_EQ(mip_fletcher(p), 0xB11Eu);
}

TEST(NmeaXor, VectorNavRegisterReply) {
  // VN-300 ICD L4328: "$VNRRG,01,VN-300T-DEV*76".
  EXPECT_EQ(nmea_xor(std::string_view("VNRRG,01,VN-300T-DEV")), 0x76u);
}

TEST(NmeaXor, HandComputed) {
  // 'A' ^ 'B' ^ 'C' = 0x41 ^ 0x42 ^ 0x43 = 0x40.
  EXPECT_EQ(nmea_xor(std::string_view("ABC")), 0x40u);
}

}  // namespace
}  // namespace navfuse::bytes

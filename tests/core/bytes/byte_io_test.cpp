#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <stdexcept>
#include <vector>

#include "core/bytes/byte_reader.hpp"
#include "core/bytes/byte_writer.hpp"

namespace navfuse::bytes {
namespace {

TEST(ByteReader, LittleAndBigEndianByHand) {
  const std::vector<std::uint8_t> d{0x01, 0x02, 0x03, 0x04};
  LeReader le(d);
  EXPECT_EQ(le.u32(), 0x04030201u);
  BeReader be(d);
  EXPECT_EQ(be.u16(), 0x0102u);
  EXPECT_EQ(be.u16(), 0x0304u);
  EXPECT_TRUE(be.ok());
}

TEST(ByteReader, FloatBigEndianFromMipDoc) {
  // MIP doc L3957: 0x3E7A63A0 = 0.24452066f (digest §11.1).
  const std::vector<std::uint8_t> d{0x3E, 0x7A, 0x63, 0xA0};
  BeReader r(d);
  EXPECT_FLOAT_EQ(r.f32(), 0.24452066f);
}

TEST(ByteReader, ReadPastEndFailsWithoutTouchingMemory) {
  const std::vector<std::uint8_t> d{0xAA, 0xBB, 0xCC};
  LeReader r(d);
  EXPECT_EQ(r.u16(), 0xBBAAu);
  EXPECT_EQ(r.u32(), 0u);  // only one byte left
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.remaining(), 0u);
  EXPECT_EQ(r.u8(), 0u);  // stays failed
  EXPECT_TRUE(r.take(1).empty());
}

TEST(ByteWriter, RoundTripEveryTypeBothEndians) {
  std::vector<std::uint8_t> buf;
  LeWriter w(buf);
  w.u8(0xFE); w.i8(-3); w.u16(0xBEEF); w.i16(-1234); w.u32(0xDEADBEEF); w.i32(-123456789);
  w.u64(0x0123456789ABCDEFull); w.i64(-987654321012345ll); w.f32(1.5f); w.f64(-2.25e-7);
  LeReader r(buf);
  EXPECT_EQ(r.u8(), 0xFE); EXPECT_EQ(r.i8(), -3); EXPECT_EQ(r.u16(), 0xBEEF); EXPECT_EQ(r.i16(), -1234);
  EXPECT_EQ(r.u32(), 0xDEADBEEFu); EXPECT_EQ(r.i32(), -123456789); EXPECT_EQ(r.u64(), 0x0123456789ABCDEFull);
  EXPECT_EQ(r.i64(), -987654321012345ll); EXPECT_EQ(r.f32(), 1.5f); EXPECT_EQ(r.f64(), -2.25e-7);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.remaining(), 0u);

  std::vector<std::uint8_t> be_buf;
  BeWriter bw(be_buf);
  bw.u32(0x01020304);
  EXPECT_EQ(be_buf, (std::vector<std::uint8_t>{1, 2, 3, 4}));
  bw.patch<std::uint16_t>(1, 0xA0B0);
  EXPECT_EQ(be_buf, (std::vector<std::uint8_t>{1, 0xA0, 0xB0, 4}));
}

TEST(SpanWriter, WritesByHandBytesInPlaceAndRefusesToOverrun) {
  // 0x0201 little-endian, 0x06050403, two bytes, three zeros: 11 bytes, counted and written.
  const std::uint8_t raw[2] = {0xAA, 0xBB};
  const auto write_all = [&](auto& w) {
    w.u16(0x0201);
    w.u32(0x06050403);
    w.bytes(raw);
    w.zeros(3);
  };
  ByteCounter counter;
  write_all(counter);
  EXPECT_EQ(counter.written(), 11u);

  std::vector<std::uint8_t> buf(12, 0x77);  // one byte more than written: must stay untouched
  LeSpanWriter w(std::span<std::uint8_t>(buf).first(11));
  write_all(w);
  EXPECT_EQ(w.written(), 11u);
  EXPECT_EQ(buf, (std::vector<std::uint8_t>{0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0xAA, 0xBB, 0, 0, 0, 0x77}));
  EXPECT_THROW(w.u8(1), std::length_error);
  EXPECT_EQ(buf[11], 0x77);
}

}  // namespace
}  // namespace navfuse::bytes

// Field parsers against the data-type examples of the Unicore spec §3 "Formats" (L174-L196).
#include <gtest/gtest.h>

#include "frontends/nmea/fields.hpp"

namespace navfuse::frontends::nmea {
namespace {

TEST(NmeaFields, UintDecimalAndHexExamples) {
  // L182-L183: "123, 4291075193" decimal; "hE10, hE41BA7C0" hex.
  EXPECT_EQ(parse_uint("123"), 123u);
  EXPECT_EQ(parse_uint("4291075193"), 4291075193u);
  EXPECT_EQ(parse_uint("hE10"), 0xE10u);
  EXPECT_EQ(parse_uint("hE41BA7C0"), 0xE41BA7C0u);
  EXPECT_EQ(parse_uint("H11"), 0x11u);  // CFGSYS example L441
  EXPECT_EQ(parse_uint("hff"), 0xFFu);  // RESET preset L246
  EXPECT_FALSE(parse_uint("h123456789"));  // more than 8 hex digits
  EXPECT_FALSE(parse_uint("4294967296"));  // above 2^32 - 1
  EXPECT_FALSE(parse_uint("-1"));
  EXPECT_FALSE(parse_uint(""));
  EXPECT_FALSE(parse_uint("h"));
  EXPECT_FALSE(parse_uint("12a"));
}

TEST(NmeaFields, Uint64Examples) {
  // L188-L190: "0xFFFFFFF, 0xFFFFFFFF", "hE41BA7C0".
  EXPECT_EQ(parse_uint64("0xFFFFFFF"), 0xFFFFFFFull);
  EXPECT_EQ(parse_uint64("0XFFFFFFFF"), 0xFFFFFFFFull);
  EXPECT_EQ(parse_uint64("hE41BA7C0"), 0xE41BA7C0ull);
  EXPECT_EQ(parse_uint64("18446744073709551615"), 18446744073709551615ull);
  EXPECT_FALSE(parse_uint64("0x10000000000000000"));  // 17 digits
}

TEST(NmeaFields, IntExamples) {
  EXPECT_EQ(parse_int("123217754"), 123217754);  // L185
  EXPECT_EQ(parse_int("-245278"), -245278);
  EXPECT_EQ(parse_int("-2147483648"), INT32_MIN);
  EXPECT_FALSE(parse_int("2147483648"));
  EXPECT_FALSE(parse_int("+5"));
}

TEST(NmeaFields, DoubleExamplesAndRejections) {
  EXPECT_DOUBLE_EQ(*parse_double("3.1415926"), 3.1415926);  // L194
  EXPECT_DOUBLE_EQ(*parse_double("-9024.12367225"), -9024.12367225);
  EXPECT_DOUBLE_EQ(*parse_double(" 082324.000"), 82324.0);  // MAPFB's leading blank (L828)
  for (const char* bad : {"", "nan", "inf", "-inf", "1e5", ".", "-", "1.2.3", "--1", "1-"}) {
    EXPECT_FALSE(parse_double(bad)) << bad;
  }
}

TEST(NmeaFields, RealKeepsDecimalsCountKeepsWidth) {
  const auto r = parse_real("0.850");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->decimals, 3);
  EXPECT_EQ(parse_real("53")->decimals, 0);
  const auto c = parse_count("007");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->value, 7u);
  EXPECT_EQ(c->width, 3);
}

TEST(NmeaFields, SplitCountsFieldsAndBoundsThem) {
  Fields f;
  ASSERT_TRUE(f.split("GPVTG,,T,,M,0.000,N,0.000,K,A"));
  EXPECT_EQ(f.size(), 10u);
  EXPECT_EQ(f.name(), "GPVTG");
  EXPECT_EQ(f[1], "");
  EXPECT_EQ(f[9], "A");
  EXPECT_EQ(f[42], "");  // past the end reads as null
  EXPECT_FALSE(f.split(std::string(kMaxFields, ',')));  // kMaxFields + 1 fields
  EXPECT_TRUE(f.split(std::string(kMaxFields - 1, ',')));
}

TEST(NmeaFields, CaseInsensitiveNames) {
  EXPECT_TRUE(iequals("cfgsave", "CFGSAVE"));  // L465 example is lower case
  EXPECT_FALSE(iequals("CFGSAVE", "CFGSAV"));
}

}  // namespace
}  // namespace navfuse::frontends::nmea

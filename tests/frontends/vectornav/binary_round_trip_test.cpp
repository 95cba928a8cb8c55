// Randomised round trips of binary messages: random groups and types (including the second
// type word and Gnss3's second group byte), random values, random-length SatInfo/RawMeas (so
// some messages exceed 600 bytes and go out as 0xFB split packets). encode -> frame -> decode
// must give back every field.
#include <gtest/gtest.h>

#include <random>

#include "core/bytes/checks.hpp"
#include "frontends/vectornav/binary_codec.hpp"
#include "frontends/vectornav/message_visit.hpp"
#include "frontends/vectornav/split_packet.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::vectornav {
namespace {

// A field "I/O" that fills every visited field with a random value (finite floats).
class RandomFiller {
 public:
  explicit RandomFiller(std::mt19937_64& rng, std::size_t max_list) : rng_(rng), max_list_(max_list) {}
  template <typename T>
  void field(std::string_view name, T& v) {
    if constexpr (std::is_floating_point_v<T>) {
      v = static_cast<T>(std::uniform_real_distribution<double>(-1e4, 1e4)(rng_));
    } else if (name == "sat_count" || name == "raw_num_sats") {
      v = static_cast<T>(std::uniform_int_distribution<std::size_t>(0, max_list_)(rng_));
    } else {
      v = static_cast<T>(rng_());
    }
  }
  template <typename T, std::size_t N>
  void fields(const std::array<std::string_view, N>& names, std::array<T, N>& v) {
    for (std::size_t i = 0; i < N; ++i) field(names[i], v[i]);
  }
  template <typename T>
  void resize(std::vector<T>& v, std::size_t n) { v.resize(n); }
  void begin_element(std::string_view, std::size_t) {}
  void end_element() {}

 private:
  std::mt19937_64& rng_;
  std::size_t max_list_;
};

BinaryMessage random_message(std::mt19937_64& rng, std::size_t max_list) {
  BinaryMessage m;
  while (m.header.groups == 0) {
    for (std::size_t slot = 0; slot < kGroupCount; ++slot) {
      if (rng() % 3 != 0) continue;
      const std::uint32_t known = known_type_mask(slot);
      std::uint32_t t = 0;
      while (t == 0) t = static_cast<std::uint32_t>(rng()) & known;
      m.header.types[slot] = t;
      m.header.groups |= 1u << group_bit(kGroups[slot]);
    }
  }
  RandomFiller filler(rng, max_list);
  visit_message(filler, m);
  return m;
}

std::vector<std::pair<std::string, FieldValue>> describe(BinaryMessage& m) {
  FrameRecord r;
  describe_binary_message(m, r);
  return r.fields;
}

TEST(VnBinaryRoundTrip, RandomGroupsTypesAndValues) {
  std::mt19937_64 rng(20240505);
  int split_messages = 0, extended = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    BinaryMessage m = random_message(rng, trial % 10 == 0 ? 40 : 3);
    std::vector<std::uint8_t> wire;
    ASSERT_TRUE(append_binary_message(m, wire, static_cast<std::uint8_t>(trial)));
    if (wire[0] == kSyncSplit) ++split_messages;
    if (m.header.types[kSlotGnss3] != 0 || (m.header.types[kSlotGnss1] >> 16) != 0) ++extended;

    VnStreamDecoder d;
    test::CollectingSink sink(true);
    test::decode_all(d, wire, sink);
    ASSERT_EQ(d.counters().bad_frames, 0u);
    ASSERT_EQ(d.counters().skipped_bytes, 0u);
    // Random enums (GnssFix 5, DeltaTime <= 0...) may be unusable for measurements; the frame
    // itself must still decode completely.
    ASSERT_EQ(d.issues(DecodeIssue::kSplitBody) + d.issues(DecodeIssue::kSplitSequence), 0u) << "trial " << trial;
    ASSERT_EQ(sink.records.size(), 1u);
    const auto expected = describe(m);
    ASSERT_EQ(sink.records[0].fields, expected) << "trial " << trial;

    // And the body decodes standalone to a message that encodes to the same bytes.
    if (wire[0] == kSyncBinary) {
      BinaryMessage back;
      ASSERT_TRUE(decode_binary_body(std::span(wire).subspan(1, wire.size() - 3), back));
      std::vector<std::uint8_t> again;
      ASSERT_TRUE(append_binary_message(back, again));
      EXPECT_EQ(again, wire);
    }
  }
  EXPECT_GT(split_messages, 20);  // the generator did exercise split packets
  EXPECT_GT(extended, 200);       // and second group bytes / type words
}

TEST(VnBinaryRoundTrip, SplitPacketsNumberedFromZeroAreAccepted) {
  // Errata A25: the nibble base is unstated; a device numbering packets 0..n-1 must decode too.
  std::mt19937_64 rng(7);
  BinaryMessage m;
  m.header.set(kSlotGnss1, gnss_type::kRawMeas);
  m.gnss[0].raw_meas.resize(40);
  RandomFiller filler(rng, 0);
  for (auto& e : m.gnss[0].raw_meas) {
    filler.field("pseudorange", e.pseudorange);
    filler.field("doppler_hz", e.doppler_hz);
  }
  std::vector<std::uint8_t> one_based;
  ASSERT_TRUE(append_binary_message(m, one_based, 9));
  ASSERT_EQ(one_based[0], kSyncSplit);
  // Renumber: low nibble - 1, recompute each packet's CRC.
  std::vector<std::uint8_t> zero_based;
  for (std::size_t i = 0; i < one_based.size();) {
    SplitPacketHeader h;
    ASSERT_EQ(parse_split_header(std::span(one_based).subspan(i + 1), h), ParseStatus::kOk);
    const std::size_t len = 1 + kSplitHeaderBytes + h.payload_bytes + kCrcBytes;
    std::vector<std::uint8_t> p(one_based.begin() + static_cast<std::ptrdiff_t>(i),
                                one_based.begin() + static_cast<std::ptrdiff_t>(i + len));
    p[3] = static_cast<std::uint8_t>(p[3] - 1);
    const std::uint16_t crc = bytes::crc16_xmodem(std::span(p).subspan(1, p.size() - 3));
    p[p.size() - 2] = static_cast<std::uint8_t>(crc >> 8);
    p[p.size() - 1] = static_cast<std::uint8_t>(crc & 0xFF);
    zero_based.insert(zero_based.end(), p.begin(), p.end());
    i += len;
  }
  for (const auto* wire : {&one_based, &zero_based}) {
    VnStreamDecoder d;
    test::CollectingSink sink(true);
    test::decode_all(d, *wire, sink);
    EXPECT_EQ(d.counters().decode_errors, 0u);
    ASSERT_EQ(sink.records.size(), 1u);
    EXPECT_EQ(sink.records[0].fields, describe(m));
  }
}

TEST(VnBinaryRoundTrip, LostSplitPacketIsADecodeError) {
  BinaryMessage m;
  m.header.set(kSlotGnss2, gnss_type::kRawMeas);
  m.gnss[1].raw_meas.resize(60);
  std::vector<std::uint8_t> wire;
  ASSERT_TRUE(append_binary_message(m, wire, 3));
  SplitPacketHeader h;
  ASSERT_EQ(parse_split_header(std::span(wire).subspan(1), h), ParseStatus::kOk);
  ASSERT_GE(h.total, 3);
  // Drop the second packet.
  const std::size_t len = 1 + kSplitHeaderBytes + h.payload_bytes + kCrcBytes;
  wire.erase(wire.begin() + static_cast<std::ptrdiff_t>(len), wire.begin() + static_cast<std::ptrdiff_t>(2 * len));
  VnStreamDecoder d;
  test::CollectingSink sink(true);
  test::decode_all(d, wire, sink);
  EXPECT_EQ(d.counters().frames, static_cast<std::uint64_t>(h.total - 1));
  EXPECT_TRUE(sink.records.empty());
  EXPECT_EQ(d.issues(DecodeIssue::kSplitSequence), 1u);
  EXPECT_EQ(d.counters().decode_errors, 1u);
}

}  // namespace
}  // namespace navfuse::frontends::vectornav

// Randomised round trip for every field and command layout in the tables: random values of the
// wire types -> encode_values -> a packet -> the framer -> FrameRecord / decode_values -> the
// same values. Independent check: the encoded length equals the length computed by hand from the
// digest §4.7 / §7.6 tables for a sample of fields.
#include <gtest/gtest.h>

#include <random>

#include "frontends/mip/field_schema.hpp"
#include "frontends/mip/frame_record.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/protocol.hpp"
#include "frontends/mip/writer.hpp"

namespace navfuse::frontends::mip {
namespace {

FieldValue random_scalar(WireType t, std::mt19937& rng) {
  std::uniform_int_distribution<std::uint64_t> u64;
  std::uniform_real_distribution<double> real(-1e4, 1e4);
  switch (t) {
    case WireType::kU8: case WireType::kBool: case WireType::kBytes16: return FieldValue{u64(rng) & 0xFF};
    case WireType::kS8: return FieldValue{static_cast<std::int64_t>(static_cast<std::int8_t>(u64(rng)))};
    case WireType::kU16: return FieldValue{u64(rng) & 0xFFFF};
    case WireType::kS16: return FieldValue{static_cast<std::int64_t>(static_cast<std::int16_t>(u64(rng)))};
    case WireType::kU32: return FieldValue{u64(rng) & 0xFFFFFFFF};
    case WireType::kS32: return FieldValue{static_cast<std::int64_t>(static_cast<std::int32_t>(u64(rng)))};
    case WireType::kU64: return FieldValue{u64(rng)};
    case WireType::kF32: case WireType::kVec3f: case WireType::kQuatf: case WireType::kMat3f:
      return FieldValue{static_cast<double>(static_cast<float>(real(rng)))};  // representable
    case WireType::kF64: case WireType::kVec3d: return FieldValue{real(rng)};
    case WireType::kChar16: case WireType::kChar32: {
      std::string s;
      const std::size_t n = u64(rng) % (wire_size(t) + 1);
      for (std::size_t i = 0; i < n; ++i) s += static_cast<char>('A' + u64(rng) % 26);
      return FieldValue{s};
    }
  }
  return FieldValue{std::uint64_t{0}};
}

// Values for a schema: Write selector for settings commands, the variant byte where one applies,
// and 0-3 repeated groups.
std::vector<FieldValue> random_values(const FieldSchema& s, std::mt19937& rng, std::size_t groups) {
  std::vector<FieldValue> v;
  std::size_t byte_offset = 0;
  for (std::size_t i = 0; i < s.params.size(); ++i) {
    const int reps = (s.repeat_from >= 0 && static_cast<int>(i) >= s.repeat_from) ? -1 : 1;
    if (reps < 0) break;
    for (std::size_t k = 0; k < scalar_count(s.params[i].type); ++k) {
      FieldValue x = random_scalar(s.params[i].type, rng);
      if (i == 0 && s.has_function) x = FieldValue{std::uint64_t{1}};
      if (s.variant_offset >= 0 && byte_offset == static_cast<std::size_t>(s.variant_offset))
        x = FieldValue{std::uint64_t{s.variant_value}};
      v.push_back(x);
    }
    byte_offset += wire_size(s.params[i].type);
  }
  if (s.repeat_from >= 0)
    for (std::size_t g = 0; g < groups; ++g)
      for (std::size_t i = static_cast<std::size_t>(s.repeat_from); i < s.params.size(); ++i)
        for (std::size_t k = 0; k < scalar_count(s.params[i].type); ++k) v.push_back(random_scalar(s.params[i].type, rng));
  return v;
}

void roundtrip(const FieldSchema& s, std::uint8_t desc_set, std::mt19937& rng) {
  SCOPED_TRACE(s.name);
  for (int trial = 0; trial < 20; ++trial) {
    const auto values = random_values(s, rng, static_cast<std::size_t>(trial % 4));
    std::vector<std::uint8_t> pkt;
    PacketWriter w(pkt, desc_set);
    ASSERT_TRUE(encode_values(s, values, w.field(s.desc)));
    w.finish();
    Framer f;
    std::vector<FrameRecord> recs;
    f.feed(pkt, [&](const PacketView& p) {
      recs.emplace_back();
      build_frame_record(p, recs.back());
      FieldWalker walk(p.payload);
      FieldView fv;
      ASSERT_TRUE(walk.next(fv));
      EXPECT_EQ(find_schema(desc_set, fv.desc, fv.data), &s);
      std::vector<std::pair<std::string, FieldValue>> back;
      ASSERT_TRUE(decode_values(s, fv.data, back));
      ASSERT_EQ(back.size(), values.size());
      for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(back[i].second, values[i]) << back[i].first;
    });
    ASSERT_EQ(recs.size(), 1u);
    ASSERT_EQ(recs[0].fields.size(), values.size());
  }
}

TEST(MipFieldRoundTrip, EveryDataFieldLayout) {
  std::mt19937 rng(21);
  for (const auto& s : data_schemas()) roundtrip(s, s.set == set::kShared ? set::kSensor : s.set, rng);
  EXPECT_GE(data_schemas().size(), 75u);
}

TEST(MipFieldRoundTrip, EveryDataFieldInTheMirroredGnssSets) {
  std::mt19937 rng(22);
  for (const auto& s : data_schemas())
    if (s.set == set::kGnss1) roundtrip(s, set::kGnss2, rng);
}

TEST(MipFieldRoundTrip, EveryCommandAndResponseLayout) {
  std::mt19937 rng(23);
  for (const auto& s : command_schemas()) {
    if (s.set == 0) continue;  // the ACK field, below in every set
    // Fallback entries (no variant) are selected only for short non-Write forms.
    bool shadowed = false;
    for (const auto& o : command_schemas())
      shadowed |= (&o != &s && o.set == s.set && o.desc == s.desc && o.variant_offset >= 0 && s.variant_offset < 0);
    if (shadowed) continue;
    roundtrip(s, s.set, rng);
  }
  for (std::uint8_t cs : {set::kBase, set::k3dm, set::kFilterCmd, set::kGnssCmd, set::kAiding})
    roundtrip(*find_schema(cs, kAckNackDescriptor, {}), cs, rng);
}

TEST(MipFieldRoundTrip, ReadSelectorSendsOnlyKeyParameters) {
  // (0x0C,0x0F) read of set 0x80 is `05 0F 02 80` (function + desc_set, digest §2.6).
  const FieldSchema* s = find_schema(set::k3dm, 0x0F, {});
  ASSERT_NE(s, nullptr);
  std::vector<std::uint8_t> data;
  bytes::BeWriter w(data);
  const std::vector<FieldValue> v = {std::uint64_t{2}, std::uint64_t{0x80}};
  ASSERT_TRUE(encode_values(*s, v, w));
  EXPECT_EQ(data, (std::vector<std::uint8_t>{0x02, 0x80}));
}

TEST(MipFieldRoundTrip, FixedSizesMatchTheDigestLengthTable) {
  // Digest §4.7 / §7.6 computed field lengths (incl. LEN and DESC bytes).
  struct L {
    std::uint8_t set, desc;
    std::size_t len;
  };
  const L lengths[] = {{0x80, 0x04, 14}, {0x80, 0x09, 38}, {0x80, 0x40, 12}, {0x82, 0x01, 28}, {0x82, 0x03, 20},
                       {0x82, 0x04, 40}, {0x82, 0x10, 8},  {0x82, 0x15, 24}, {0x82, 0x43, 17}, {0x82, 0x49, 19},
                       {0x82, 0x50, 31}, {0x82, 0x51, 27}, {0x91, 0x03, 44}, {0x91, 0x04, 32}, {0x91, 0x05, 36},
                       {0x91, 0x22, 63}, {0x91, 0x61, 220}, {0x91, 0x62, 104}, {0x93, 0x30, 46}, {0x93, 0x31, 52},
                       {0xA0, 0x01, 18}, {0x80, 0xD3, 14}, {0x80, 0xD7, 12}, {0x13, 0x21, 51}, {0x13, 0x23, 23},
                       {0x13, 0x2A, 39}, {0x0D, 0x52, 43}, {0x0D, 0x55, 29}, {0x0C, 0x33, 39}, {0x0E, 0x20, 81},
                       {0x0C, 0x43, 12}, {0x0D, 0x1C, 27}};
  for (const auto& l : lengths) {
    const FieldSchema* s = find_schema(l.set, l.desc, {});
    ASSERT_NE(s, nullptr) << int(l.set) << " " << int(l.desc);
    EXPECT_EQ(fixed_size(*s) + kFieldHeaderSize, l.len) << s->name;
  }
}

}  // namespace
}  // namespace navfuse::frontends::mip

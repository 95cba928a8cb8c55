// The per-type payload bounds the framer checks before any CRC (payload_bound.hpp,
// message_catalog.cpp, issue 15.11): each variable-length type's bound equals the spec's size
// formula at its count fields' largest values (or the documented cap of an open layout); the
// largest message the writer can produce for every type fits its bound and frames; a header
// claiming one byte more than the bound is dropped at once, one claiming the bound is waited for.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/payload_bound.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

template <class F>
void for_each_message(F&& f) {
  std::apply([&](auto... m) { (f(m), ...); }, AllMessages{});
}

// Largest payload of each variable-length type, from the spec's own size formulas (digest §3
// catalogue, "+var" rows) at the largest value of each count / length field's type, not from
// the structs: a hand computation to check payload_bound() against.
const std::map<MessageType, std::uint64_t>& spec_bounds() {
  constexpr std::uint64_t kU8 = 255, kU16 = 65535;
  constexpr std::uint64_t kOpaque = 64 * 1024;  // documented cap, wire.hpp kMaxOpaqueDataSize
  static const std::map<MessageType, std::uint64_t> bounds{
      {MessageType::kGnssSatellite, 20 + 12 * kU16},            // 20 + 12 N, N u16 (L1815-1846)
      {MessageType::kGnssSignals, 32 + 8 * kU8 + 8 * kU16},     // 32 + 8 N + 8 S, u8 / u16 (L1949-2019)
      {MessageType::kMessageRateResponse, 8 + 8 * kU16},        // 8 + 8 N, N u16 (L1655-1690)
      {MessageType::kSupportedIoInterfaces, 8 + 4 * kU8},       // 8 + 4 N, N u8 (L1694-1711)
      {MessageType::kVersionInfo, 16 + 4 * kU8},                // four u8 lengths; 1036 needs no padding
      {MessageType::kEventNotification, 24 + kU16},             // u16 description length
      {MessageType::kDeviceId, 16 + 3 * kU8},                   // 16 + x + y + z, u8 each
      {MessageType::kLBandFrame, 20 + kU16},                    // 20 + n, u16 user data size
      {MessageType::kFaultControl, 20 + 1},                     // values are None, u8 or bool (L859-870)
      {MessageType::kSetConfig, 8 + 8 + 64},                    // InterfaceConfig REMOTE_ADDRESS char[64]
      {MessageType::kConfigResponse, 12 + 8 + 64},              //   is the largest value (L1211-1228)
      {MessageType::kImportData, 16 + kOpaque},
      {MessageType::kPlatformStorageData, 12 + kOpaque},
      {MessageType::kInputDataWrapper, 8 + kOpaque},
      {MessageType::kSta5635IqData, 4 + kOpaque},
  };
  return bounds;
}

TEST(FePayloadBound, EveryTypeIsBoundedByItsLayout) {
  std::size_t variable = 0;
  for_each_message([&](auto msg) {
    using M = decltype(msg);
    PayloadBound walk;
    msg.visit(walk);
    EXPECT_EQ(walk.fixed_bytes(), M::kSize) << M::kName;
    const std::uint64_t layout = payload_bound<M>();
    ASSERT_NE(layout, 0u) << M::kName << ": open layout without kMaxVariableSize, or one it does not need";
    const std::uint32_t bound = max_payload_size(to_u16(M::kType));
    EXPECT_EQ(bound, layout + kMaxVersionGrowth) << M::kName;
    EXPECT_LT(bound, kMaxPayloadSize) << M::kName;
    const auto spec = spec_bounds().find(M::kType);
    if (spec == spec_bounds().end()) {
      EXPECT_EQ(layout, M::kSize) << M::kName << " is variable-length: add its spec formula above";
    } else {
      ++variable;
      EXPECT_EQ(layout, spec->second) << M::kName;
    }
  });
  EXPECT_EQ(variable, spec_bounds().size());  // every formula above belongs to a catalogue type
}

// Grows every count / length to its bound (after PayloadBound set the count fields to their
// largest values), capping an open layout's variable part at M's kMaxVariableSize.
class GrowToBound {
 public:
  explicit GrowToBound(std::uint64_t cap) : cap_(cap) {}
  template <typename T>
  void field(std::string_view, T&) {}
  template <typename T, std::size_t N>
  void array(std::string_view, std::array<T, N>&) {}
  void timestamp(std::string_view, Timestamp&) {}
  void reserved(std::size_t) {}
  void text(std::string_view, std::string& s, std::size_t length) { s.assign(capped(length), 'v'); }
  void blob(std::string_view, std::vector<std::uint8_t>& b, std::size_t length) { b.assign(capped(length), 0xA5); }
  void config_value(std::string_view n, std::uint16_t, std::vector<std::uint8_t>& b, std::size_t length) {
    blob(n, b, length);
  }
  void rest(std::string_view n, std::vector<std::uint8_t>& b) { blob(n, b, cap_); }
  template <class E>
  void list(std::string_view, std::vector<E>& entries, std::size_t count) {
    entries.resize(count);
    for (auto& e : entries) {
      PayloadBound max_counts;
      e.visit(max_counts);
      e.visit(*this);
    }
  }

 private:
  std::size_t capped(std::size_t n) const { return static_cast<std::size_t>(std::min<std::uint64_t>(n, cap_)); }
  std::uint64_t cap_;
};

template <class M>
M largest_message() {
  M msg;
  PayloadBound max_counts;
  msg.visit(max_counts);
  std::uint64_t cap = kMaxPayloadSize;  // a missing kMaxVariableSize must fail, not allocate 4 GiB
  if constexpr (requires { M::kMaxVariableSize; }) cap = M::kMaxVariableSize;
  GrowToBound grow(cap);
  msg.visit(grow);
  return msg;
}

TEST(FePayloadBound, LargestMessageTheWriterProducesFitsAndFrames) {
  for_each_message([&](auto msg) {
    using M = decltype(msg);
    std::vector<std::uint8_t> bytes;
    FusionEngineWriter writer;
    writer.append(largest_message<M>(), bytes);
    const std::size_t payload = bytes.size() - kHeaderSize;
    EXPECT_LE(payload, max_payload_size(to_u16(M::kType))) << M::kName;
    // Not just within: the bound is reached, so it is no larger than the layout needs.
    EXPECT_EQ(payload, payload_bound<M>()) << M::kName;

    Framer framer;
    std::size_t frames = 0;
    framer.feed(bytes, [&](const Frame& f) {
      ++frames;
      M back;
      EXPECT_TRUE(decode_payload(f.payload, back)) << M::kName;
    });
    EXPECT_EQ(frames, 1u) << M::kName;
    EXPECT_EQ(framer.counters().bad_frames, 0u) << M::kName;
  });
}

// A header naming `type` and claiming `size` payload bytes (CRC 0: it can never pass), followed
// by a few valid frames.
struct ClaimStream {
  std::vector<std::uint8_t> bytes;
  std::size_t valid_frames = 0;
};
ClaimStream claim_then_frames(std::uint16_t type, std::uint32_t size) {
  ClaimStream s;
  s.bytes.assign(kHeaderSize, 0);
  s.bytes[0] = kSync0;
  s.bytes[1] = kSync1;
  for (int i = 0; i < 2; ++i) s.bytes[kMessageTypeOffset + i] = static_cast<std::uint8_t>(type >> (8 * i));
  for (int i = 0; i < 4; ++i) s.bytes[kPayloadSizeOffset + i] = static_cast<std::uint8_t>(size >> (8 * i));
  FusionEngineWriter writer;
  for (int i = 0; i < 3; ++i) {
    writer.append(ImuOutputMessage{}, s.bytes);
    writer.append(GnssSignalsMessage{}, s.bytes);
    s.valid_frames += 2;
  }
  return s;
}

TEST(FePayloadBound, ClaimBeyondTheBoundIsDroppedAtOnceAndTheBoundItselfIsWaitedFor) {
  std::vector<std::uint16_t> types{0x7FF0};  // and one id the catalogue does not define
  for_each_message([&](auto msg) { types.push_back(to_u16(decltype(msg)::kType)); });
  for (const std::uint16_t type : types) {
    const std::uint32_t bound = max_payload_size(type);
    {
      // bound + 1: rejected on the header alone. The frames behind it arrive during feed(),
      // before finish(), so the framer neither waited for the claimed bytes nor CRC'd them
      // (they were never there: the stream is far shorter than any bound).
      const ClaimStream s = claim_then_frames(type, bound + 1);
      ASSERT_LT(s.bytes.size(), kHeaderSize + bound);
      Framer framer;
      std::size_t frames = 0;
      framer.feed(s.bytes, [&](const Frame&) { ++frames; });
      EXPECT_EQ(frames, s.valid_frames) << type;
      EXPECT_EQ(framer.counters().bad_frames, 1u) << type;
      EXPECT_EQ(framer.counters().skipped_bytes, kHeaderSize) << type;
      EXPECT_EQ(framer.buffered_bytes(), 0u) << type;
    }
    {
      // The bound itself passes the size check: the framer waits for the payload (nothing is
      // framed before finish()), then gives the candidate up and recovers every frame behind it.
      const ClaimStream s = claim_then_frames(type, bound);
      Framer framer;
      std::size_t frames = 0;
      auto count = [&](const Frame&) { ++frames; };
      framer.feed(s.bytes, count);
      EXPECT_EQ(frames, 0u) << type;
      EXPECT_EQ(framer.buffered_bytes(), s.bytes.size()) << type;
      framer.finish(count);
      EXPECT_EQ(frames, s.valid_frames) << type;
    }
  }
}

}  // namespace
}  // namespace navfuse::frontends::fusionengine

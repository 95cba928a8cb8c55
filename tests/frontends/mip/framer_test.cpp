// Framer robustness: checksum equivalence, resynchronisation after garbage and bad packets,
// truncation at every length, single-bit flips, absurd lengths and field walks, and chunked
// feeding at random split points giving exactly the single-feed result.
#include <gtest/gtest.h>

#include <random>

#include "core/bytes/checks.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/writer.hpp"
#include "tests/frontends/mip/test_util.hpp"

namespace navfuse::frontends::mip {
namespace {

struct Seen {
  std::uint64_t offset;
  std::uint8_t set;
  std::size_t size;
  bool operator==(const Seen&) const = default;
};

std::vector<Seen> frame_all(Framer& f, std::span<const std::uint8_t> bytes) {
  std::vector<Seen> seen;
  f.feed(bytes, [&](const PacketView& p) { seen.push_back({p.offset, p.desc_set, p.bytes.size()}); });
  return seen;
}

void finish_into(Framer& f, std::vector<Seen>& seen) {
  f.finish([&](const PacketView& p) { seen.push_back({p.offset, p.desc_set, p.bytes.size()}); });
}

// A packet with `n_fields` random fields of random sizes in set 0x80.
std::vector<std::uint8_t> random_packet(std::mt19937& rng, int n_fields) {
  std::vector<std::uint8_t> out;
  PacketWriter w(out, 0x80);
  std::uniform_int_distribution<int> len(0, 40), byte(0, 255);
  for (int i = 0; i < n_fields; ++i) {
    auto& f = w.field(static_cast<std::uint8_t>(byte(rng)));
    const int n = len(rng);
    for (int k = 0; k < n; ++k) f.u8(static_cast<std::uint8_t>(byte(rng)));
  }
  w.finish();
  return out;
}

TEST(MipFramer, FastFletcherEqualsCoreChecksum) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> byte(0, 255);
  for (std::size_t n = 0; n < 600; ++n) {
    std::vector<std::uint8_t> b(n);
    for (auto& x : b) x = static_cast<std::uint8_t>(byte(rng));
    ASSERT_EQ(fletcher_fast(b.data(), b.size()), bytes::mip_fletcher(b)) << n;
  }
}

TEST(MipFramer, GarbageBetweenPacketsIsSkippedAndCounted) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> byte(0, 255), glen(0, 50);
  std::vector<std::uint8_t> stream;
  std::vector<std::uint64_t> offsets;
  std::size_t garbage = 0;
  for (int i = 0; i < 200; ++i) {
    const int g = glen(rng);
    for (int k = 0; k < g; ++k) stream.push_back(i % 7 == 0 ? 0x75 : static_cast<std::uint8_t>(byte(rng)));
    garbage += static_cast<std::size_t>(g);
    offsets.push_back(stream.size());
    const auto p = random_packet(rng, 1 + i % 5);
    stream.insert(stream.end(), p.begin(), p.end());
  }
  Framer f;
  auto seen = frame_all(f, stream);
  finish_into(f, seen);
  ASSERT_EQ(seen.size(), offsets.size());
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i].offset, offsets[i]);
  EXPECT_EQ(f.counters().frames, 200u);
  EXPECT_EQ(f.counters().skipped_bytes, garbage);
  EXPECT_EQ(f.counters().bytes, stream.size());
}

TEST(MipFramer, ChunkedFeedingEqualsSingleFeed) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<std::uint8_t> stream;
  for (int i = 0; i < 300; ++i) {
    const auto p = random_packet(rng, 1 + i % 9);
    stream.insert(stream.end(), p.begin(), p.end());
  }
  for (auto& b : stream)  // 1% corruption: bad checksums, false syncs, broken lengths
    if (byte(rng) < 3) b = static_cast<std::uint8_t>(byte(rng));
  Framer whole;
  auto expected = frame_all(whole, stream);
  finish_into(whole, expected);
  for (int trial = 0; trial < 50; ++trial) {
    Framer f;
    std::vector<Seen> seen;
    std::uniform_int_distribution<std::size_t> cut(0, trial < 10 ? 3 : 700);
    std::size_t pos = 0;
    while (pos < stream.size()) {
      const std::size_t n = std::min(stream.size() - pos, cut(rng));
      auto part = frame_all(f, std::span<const std::uint8_t>(stream).subspan(pos, n));
      seen.insert(seen.end(), part.begin(), part.end());
      pos += n;
    }
    finish_into(f, seen);
    ASSERT_EQ(seen, expected) << trial;
    EXPECT_EQ(f.counters().frames, whole.counters().frames);
    EXPECT_EQ(f.counters().bad_frames, whole.counters().bad_frames);
    EXPECT_EQ(f.counters().skipped_bytes, whole.counters().skipped_bytes);
  }
  // Every byte is either in a packet or skipped.
  std::size_t framed = 0;
  for (const auto& s : expected) framed += s.size;
  EXPECT_EQ(framed + whole.counters().skipped_bytes, stream.size());
}

TEST(MipFramer, TruncationAtEveryLengthThenAValidPacket) {
  std::mt19937 rng(5);
  const auto p = random_packet(rng, 4);
  const auto q = random_packet(rng, 2);
  for (std::size_t k = 0; k < p.size(); ++k) {
    Framer alone;
    auto none = frame_all(alone, std::span<const std::uint8_t>(p).first(k));
    EXPECT_TRUE(none.empty());
    EXPECT_EQ(alone.counters().skipped_bytes + alone.buffered(), k);
    finish_into(alone, none);
    EXPECT_TRUE(none.empty());
    EXPECT_EQ(alone.counters().skipped_bytes, k);
    EXPECT_EQ(alone.counters().frames, 0u);

    std::vector<std::uint8_t> s(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(k));
    s.insert(s.end(), q.begin(), q.end());
    Framer f;
    auto seen = frame_all(f, s);
    finish_into(f, seen);
    ASSERT_EQ(seen.size(), 1u) << k;
    EXPECT_EQ(seen[0].offset, k);
    EXPECT_EQ(f.counters().skipped_bytes, k);
  }
}

TEST(MipFramer, EverySingleBitFlipIsRejected) {
  const auto p = test::hex("7565 800E 0E04 3E7A 63A0 BB8E 3B29 7FE5 BF7F 84EE");  // L3957
  for (std::size_t i = 0; i < p.size() * 8; ++i) {
    auto c = p;
    c[i / 8] ^= static_cast<std::uint8_t>(1u << (i % 8));
    Framer f;
    auto seen = frame_all(f, c);
    finish_into(f, seen);
    EXPECT_TRUE(seen.empty()) << "bit " << i;
    EXPECT_EQ(f.counters().skipped_bytes, c.size());
  }
}

// A packet with a correct checksum over a broken field walk (digest §2.2 parser rules).
std::vector<std::uint8_t> with_checksum(std::vector<std::uint8_t> body) {
  const auto ck = bytes::mip_fletcher(body);
  body.push_back(static_cast<std::uint8_t>(ck >> 8));
  body.push_back(static_cast<std::uint8_t>(ck & 0xFF));
  return body;
}

TEST(MipFramer, BadFieldWalksAndAbsurdLengthsAreBadFrames) {
  const auto good = test::hex("75650102 0201 E0C6");  // Ping (L3901)
  const std::vector<std::vector<std::uint8_t>> bad = {
      with_checksum({0x75, 0x65, 0x80, 0x03, 0x01, 0x04, 0x00}),        // field LEN 1
      with_checksum({0x75, 0x65, 0x80, 0x02, 0x00, 0x04}),              // field LEN 0
      with_checksum({0x75, 0x65, 0x80, 0x04, 0x06, 0x04, 0x00, 0x00}),  // field past the payload end
      with_checksum({0x75, 0x65, 0x80, 0x03, 0x02, 0x04, 0x05}),        // trailing partial field
  };
  for (const auto& b : bad) {
    std::vector<std::uint8_t> s = b;
    s.insert(s.end(), good.begin(), good.end());
    Framer f;
    auto seen = frame_all(f, s);
    finish_into(f, seen);
    ASSERT_EQ(seen.size(), 1u);
    EXPECT_EQ(seen[0].offset, b.size());
    EXPECT_EQ(f.counters().bad_frames, 1u);
    EXPECT_EQ(f.counters().skipped_bytes, b.size());
  }
  // A header announcing 255 payload bytes of junk, then the ping inside the "payload".
  std::vector<std::uint8_t> s = {0x75, 0x65, 0x80, 0xFF};
  s.insert(s.end(), good.begin(), good.end());
  s.resize(s.size() + 300, 0xAA);
  Framer f;
  auto seen = frame_all(f, s);
  finish_into(f, seen);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].offset, 4u);
  EXPECT_EQ(f.counters().bad_frames, 1u);
  EXPECT_EQ(f.counters().skipped_bytes, s.size() - good.size());
}

TEST(MipFramer, EmptyPayloadPacketIsValid) {
  const auto p = with_checksum({0x75, 0x65, 0x80, 0x00});
  Framer f;
  EXPECT_EQ(frame_all(f, p).size(), 1u);
}

}  // namespace
}  // namespace navfuse::frontends::mip

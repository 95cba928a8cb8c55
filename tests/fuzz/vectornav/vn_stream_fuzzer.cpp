// libFuzzer target: arbitrary bytes into the VN-300 StreamDecoder (fed in chunks whose sizes
// come from the input, so split frames are exercised), into the binary body decoder and into
// the command-reply parser. Checks the counter invariants after every feed.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>

#include "frontends/vectornav/binary_codec.hpp"
#include "frontends/vectornav/commands.hpp"
#include "frontends/vectornav/decoder.hpp"

namespace {

using namespace navfuse::frontends;

struct Sink : DecodeSink {
  std::size_t measurements = 0;
  void on_measurement(const navfuse::Measurement&) override { ++measurements; }
  void on_frame(const FrameRecord& r) override {
    if (r.protocol != "vn") std::abort();
  }
  bool wants_frames() const override { return true; }
};

void check(const vectornav::VnStreamDecoder& d) {
  const StreamCounters& k = d.counters();
  // Every byte fed is framed, skipped or still buffered; at most one frame is buffered.
  if (k.bytes != d.framed_bytes() + k.skipped_bytes + d.buffered_bytes()) std::abort();
  if (d.buffered_bytes() > vectornav::kMaxAsciiSentenceBytes + vectornav::kMaxBinaryPacketBytes) std::abort();
  if (k.unknown_frames > k.frames || k.bad_frames > k.skipped_bytes) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);
  vectornav::VnStreamDecoder d;
  Sink sink;
  // Chunk sizes from the input's own bytes: 1..64.
  std::size_t at = 0, k = 0;
  while (at < size) {
    const std::size_t n = std::min<std::size_t>(size - at, 1 + (data[k++ % size] & 0x3F));
    d.feed(in.subspan(at, n), sink);
    check(d);
    at += n;
  }
  d.finish(sink);
  check(d);
  if (d.buffered_bytes() != 0) std::abort();

  // The same bytes as a message body and as a device reply.
  vectornav::BinaryMessage m;
  if (vectornav::decode_binary_body(in, m)) {
    FrameRecord r;
    vectornav::describe_binary_message(m, r);
  }
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (const auto reply = vectornav::cmd::parse_reply(text)) {
    (void)vectornav::cmd::parse_binary_output(*reply);
    (void)vectornav::cmd::parse_reference_frame_rotation(*reply);
    (void)vectornav::cmd::parse_compass_baseline(*reply);
    (void)vectornav::cmd::parse_ins_basic_config(*reply);
  }
  return 0;
}

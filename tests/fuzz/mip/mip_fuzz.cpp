// Fuzz target: arbitrary bytes through the MIP StreamDecoder (whole and in chunks whose sizes come
// from the input), the AidingCommandHandler and the CommandResponder. Checks the counter
// invariants: the same frames/bad/skipped however the bytes are chunked, frames + bad frames
// bounded by the bytes, and every byte accounted for after finish().
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "frontends/mip/decoder.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/responder.hpp"

namespace {

using namespace navfuse;
using namespace navfuse::frontends;

struct NullSink : DecodeSink {
  bool frames;
  explicit NullSink(bool f) : frames(f) {}
  void on_measurement(const Measurement&) override {}
  bool wants_frames() const override { return frames; }
};

void check(bool ok) {
  if (!ok) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);

  mip::MipDecoder whole;
  NullSink sink_a(true);
  whole.feed(in, sink_a);
  whole.finish(sink_a);

  mip::MipDecoder chunked;
  NullSink sink_b(false);
  std::size_t pos = 0;
  std::size_t step = size > 0 ? (data[0] % 17) + 1 : 1;
  while (pos < size) {
    const std::size_t n = std::min(step, size - pos);
    chunked.feed(in.subspan(pos, n), sink_b);
    pos += n;
    step = (step * 7 + 3) % 29 + 1;
  }
  chunked.finish(sink_b);

  const auto& a = whole.counters();
  const auto& b = chunked.counters();
  check(a.bytes == size && b.bytes == size);
  check(a.frames == b.frames && a.bad_frames == b.bad_frames && a.skipped_bytes == b.skipped_bytes);
  check(a.skipped_bytes <= size);
  check(a.frames * mip::kWrapperSize <= size);
  check(a.bad_frames <= a.skipped_bytes);

  mip::Framer f;
  std::size_t framed = 0;
  f.feed(in, [&](const mip::PacketView& p) { framed += p.bytes.size(); });
  f.finish([&](const mip::PacketView& p) { framed += p.bytes.size(); });
  check(framed + f.counters().skipped_bytes == size);

  // The input as one command packet (to a responder and to the aiding handler).
  std::vector<std::uint8_t> reply;
  std::vector<Measurement> aiding;
  mip::CommandResponder dev;
  dev.handle_packet(in, reply, aiding);
  mip::AidingCommandHandler handler;
  mip::AidingResult result;
  handler.handle_packet(in, result);
  return 0;
}

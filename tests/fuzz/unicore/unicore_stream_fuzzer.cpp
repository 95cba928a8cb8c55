// libFuzzer target: any bytes into the UM220 decoder, the reply reader and parse_reply_line.
// Invariants: every fed byte is accounted for, frames bound their sub-counters, feeding the same
// bytes in chunks gives the same counters and measurement count as one feed, and no measurement
// leaves with a non-finite time base.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "frontends/unicore/commands_reply.hpp"
#include "frontends/unicore/decoder.hpp"

namespace {

using namespace navfuse;

class Sink : public frontends::DecodeSink {
 public:
  void on_measurement(const Measurement& m) override {
    ++count;
    if (header_of(m).time_source != TimeSource::kGps) __builtin_trap();
  }
  void on_frame(const frontends::FrameRecord& r) override { fields += r.fields.size(); }
  bool wants_frames() const override { return true; }
  std::size_t count = 0;
  std::size_t fields = 0;
};

void check(const frontends::StreamCounters& c, std::size_t size) {
  // The shortest sentence is 3 bytes ("$X\r"); a rejected candidate can be a lone '$'.
  constexpr std::size_t kMinSentenceBytes = 3;
  if (c.bytes != size || c.skipped_bytes > c.bytes || c.unknown_frames + c.decode_errors > c.frames ||
      c.frames * kMinSentenceBytes > c.bytes || c.bad_frames > c.bytes) {
    __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);

  frontends::unicore::DecoderOptions options;
  options.odometer_m_per_pulse = 0.02;
  frontends::unicore::UnicoreDecoder whole(options);
  Sink a;
  whole.feed(bytes, a);
  whole.finish(a);
  check(whole.counters(), size);

  // The same bytes in chunks whose sizes come from the data itself.
  frontends::unicore::UnicoreDecoder chunked(options);
  Sink b;
  std::size_t at = 0;
  std::size_t step = size > 0 ? (data[0] % 61) + 1 : 1;
  while (at < size) {
    const std::size_t n = std::min(step, size - at);
    chunked.feed(bytes.subspan(at, n), b);
    at += n;
    step = (step * 7 + 3) % 97 + 1;
  }
  chunked.finish(b);
  const auto& x = whole.counters();
  const auto& y = chunked.counters();
  if (x.frames != y.frames || x.bad_frames != y.bad_frames || x.skipped_bytes != y.skipped_bytes ||
      x.unknown_frames != y.unknown_frames || x.decode_errors != y.decode_errors || a.count != b.count) {
    __builtin_trap();
  }

  frontends::unicore::ReplyReader reader;
  std::size_t replies = 0;
  reader.feed(bytes, [&](const frontends::unicore::Reply&) { ++replies; });
  if (replies > reader.counters().frames) __builtin_trap();
  const auto line = frontends::unicore::parse_reply_line(
      std::string_view(reinterpret_cast<const char*>(data), std::min<std::size_t>(size, 256)));
  if (line && line->fields.size() == 0) __builtin_trap();
  return 0;
}

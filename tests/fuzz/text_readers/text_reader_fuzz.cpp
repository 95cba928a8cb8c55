// Fuzz target for a text reader (imutxt or rtklib, chosen at build time by NAVFUSE_FUZZ_FORMAT):
// arbitrary bytes through its StreamDecoder whole and in chunks whose sizes come from the input,
// and through its detection probe. Checks the counter invariants: the same counts however the
// bytes are chunked, every byte fed counted, skipped bytes within the input, no more lines
// (frames + bad + unknown) than line ends + 1, and every measurement finite.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "frontends/imutxt/decoder.hpp"
#include "frontends/imutxt/frontend.hpp"
#include "frontends/rtklib/decoder.hpp"
#include "frontends/rtklib/frontend.hpp"

namespace {

using namespace navfuse;
using namespace navfuse::frontends;

void check(bool ok) {
  if (!ok) std::abort();
}

struct CheckingSink : DecodeSink {
  bool frames;
  explicit CheckingSink(bool f) : frames(f) {}
  void on_measurement(const Measurement& m) override {
    if (const auto* i = std::get_if<ImuSample>(&m)) {
      check(i->gyro.allFinite() && i->accel.allFinite() && std::isfinite(i->dt_s) && i->dt_s >= 0.0);
    } else if (const auto* p = std::get_if<GnssPosition>(&m)) {
      check(std::isfinite(p->lat_rad) && std::isfinite(p->lon_rad) && p->cov_ned_m2.allFinite());
    }
  }
  bool wants_frames() const override { return frames; }
};

std::unique_ptr<StreamDecoder> make() {
#if NAVFUSE_FUZZ_FORMAT == 1
  return std::make_unique<imutxt::ImuTextDecoder>(2381);
#else
  return std::make_unique<rtklib::PosDecoder>();
#endif
}

const FrontendInfo& info() {
#if NAVFUSE_FUZZ_FORMAT == 1
  return imutxt::frontend();
#else
  return rtklib::frontend();
#endif
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);
  auto whole = make();
  CheckingSink sink_a(true);
  whole->feed(in, sink_a);
  whole->finish(sink_a);

  auto chunked = make();
  CheckingSink sink_b(false);
  std::size_t pos = 0;
  std::size_t step = size > 0 ? (data[0] % 17) + 1 : 1;
  while (pos < size) {
    const std::size_t n = std::min(step, size - pos);
    chunked->feed(in.subspan(pos, n), sink_b);
    pos += n;
    step = (step * 7 + 3) % 29 + 1;
  }
  chunked->finish(sink_b);

  const auto& a = whole->counters();
  const auto& b = chunked->counters();
  check(a.bytes == size && b.bytes == size);
  check(a.frames == b.frames && a.bad_frames == b.bad_frames && a.skipped_bytes == b.skipped_bytes &&
        a.unknown_frames == b.unknown_frames);
  check(a.skipped_bytes <= size);
  std::size_t line_ends = 0;
  for (std::uint8_t c : in) line_ends += c == '\n' ? 1 : 0;
  check(a.frames + a.bad_frames + a.unknown_frames <= line_ends + 1);
  check(info().probe(in) <= line_ends + 1);
  return 0;
}

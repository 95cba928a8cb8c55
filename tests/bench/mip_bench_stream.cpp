// The MIP benchmark stream outside the benchmark, for comparing navfuse with MicroStrain's own
// parser (mip_sdk's mip_parser, mip_vendor_compare.sh) on the same bytes. Command line:
// bench_stream_tool.hpp; `write` writes navfuse_mip_bench's stream (mip_bench_stream.hpp), `frame`
// runs the Framer (valid packets counted per descriptor set) or (--decode) the MipDecoder over it.
#include "frontends/mip/decoder.hpp"
#include "frontends/mip/framer.hpp"
#include "tests/bench/bench_stream_tool.hpp"
#include "tests/bench/mip_bench_stream.hpp"

namespace {

using namespace navfuse;
namespace mip = frontends::mip;

bool frame_once(const std::string& path, std::size_t chunk, bool decode, bench::StreamPass& pass) {
  if (decode) {
    mip::MipDecoder decoder;
    bench::CountingSink sink;
    const bool ok = bench::read_in_chunks(
        path, chunk, [&](std::span<const std::uint8_t> b) { decoder.feed(b, sink); }, [&] { decoder.finish(sink); });
    pass.bytes = decoder.counters().bytes;
    pass.frames = decoder.counters().frames;
    pass.bad = decoder.counters().bad_frames;
    pass.measurements = sink.measurements;
    return ok;
  }
  mip::Framer framer;
  auto count = [&](const mip::PacketView& p) { ++pass.by_type[p.desc_set]; };
  const bool ok = bench::read_in_chunks(
      path, chunk, [&](std::span<const std::uint8_t> b) { framer.feed(b, count); }, [&] { framer.finish(count); });
  pass.bytes = framer.counters().bytes;
  pass.frames = framer.counters().frames;
  pass.bad = framer.counters().bad_frames;
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const bench::StreamTool tool{"navfuse_mip_bench_stream",
                               [](bool) { return bench::mip_bench_stream(1, bench::kCorruptedStreamBytes); },
                               frame_once};
  return bench::run_stream_tool(tool, argc, argv);
}

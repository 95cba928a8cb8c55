// The FusionEngine benchmark stream outside the benchmark, for comparing navfuse with Point One's
// own parser (fe_vendor_compare.sh) on the same bytes. Command line: bench_stream_tool.hpp;
// `write` writes navfuse_fe_bench's stream (fusionengine_bench_stream.hpp; --signals adds its
// GNSSSignals messages), `frame` runs the Framer or (--decode) the FusionEngineDecoder over it.
#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "tests/bench/bench_stream_tool.hpp"
#include "tests/bench/fusionengine_bench_stream.hpp"

namespace {

using namespace navfuse;
namespace fe = frontends::fusionengine;

bool frame_once(const std::string& path, std::size_t chunk, bool decode, bench::StreamPass& pass) {
  if (decode) {
    fe::FusionEngineDecoder decoder;
    bench::CountingSink sink;
    const bool ok = bench::read_in_chunks(
        path, chunk, [&](std::span<const std::uint8_t> b) { decoder.feed(b, sink); }, [&] { decoder.finish(sink); });
    pass.bytes = decoder.counters().bytes;
    pass.frames = decoder.counters().frames;
    pass.bad = decoder.counters().bad_frames;
    pass.measurements = sink.measurements;
    return ok;
  }
  fe::Framer framer;
  auto count = [&](const fe::Frame& f) { ++pass.by_type[f.header.message_type]; };
  const bool ok = bench::read_in_chunks(
      path, chunk, [&](std::span<const std::uint8_t> b) { framer.feed(b, count); }, [&] { framer.finish(count); });
  pass.bytes = framer.counters().bytes;
  pass.frames = framer.counters().frames;
  pass.bad = framer.counters().bad_frames;
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const bench::StreamTool tool{
      "navfuse_fe_bench_stream",
      [](bool signals) { return bench::fe_bench_stream(0.01, signals, bench::kCorruptedStreamBytes); },
      frame_once};
  return bench::run_stream_tool(tool, argc, argv);
}

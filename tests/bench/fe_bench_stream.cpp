// The FusionEngine benchmark stream outside the benchmark, for comparing navfuse with Point One's
// own parser (fe_vendor_compare.sh) on the same bytes. Command line: bench_stream_tool.hpp;
// `write` writes navfuse_fe_bench's stream (fusionengine_bench_stream.hpp; --signals adds its
// GNSSSignals messages), `frame` runs the Framer or (--decode) the FusionEngineDecoder over it.
#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "tests/bench/bench_stream_tool.hpp"
#include "tests/bench/fusionengine_bench_stream.hpp"

int main(int argc, char** argv) {
  using namespace navfuse;
  namespace fe = frontends::fusionengine;
  const bench::StreamTool tool{
      "navfuse_fe_bench_stream",
      [](bool signals) { return bench::fe_bench_stream(0.01, signals, bench::kCorruptedStreamBytes); },
      [](const std::string& path, std::size_t chunk, bool decode, bench::StreamPass& pass) {
        return bench::frame_once_with<fe::Framer, fe::FusionEngineDecoder>(
            path, chunk, decode, pass, [](const fe::Frame& f) { return unsigned{f.header.message_type}; });
      }};
  return bench::run_stream_tool(tool, argc, argv);
}

// The MIP benchmark stream outside the benchmark, for comparing navfuse with MicroStrain's own
// parser (mip_sdk's mip_parser, mip_vendor_compare.sh) on the same bytes. Command line:
// bench_stream_tool.hpp; `write` writes navfuse_mip_bench's stream (mip_bench_stream.hpp), `frame`
// runs the Framer (valid packets counted per descriptor set) or (--decode) the MipDecoder over it.
#include "frontends/mip/decoder.hpp"
#include "frontends/mip/framer.hpp"
#include "tests/bench/bench_stream_tool.hpp"
#include "tests/bench/mip_bench_stream.hpp"

int main(int argc, char** argv) {
  using namespace navfuse;
  namespace mip = frontends::mip;
  const bench::StreamTool tool{
      "navfuse_mip_bench_stream", [](bool) { return bench::mip_bench_stream(1, bench::kCorruptedStreamBytes); },
      [](const std::string& path, std::size_t chunk, bool decode, bench::StreamPass& pass) {
        return bench::frame_once_with<mip::Framer, mip::MipDecoder>(
            path, chunk, decode, pass, [](const mip::PacketView& p) { return unsigned{p.desc_set}; });
      }};
  return bench::run_stream_tool(tool, argc, argv);
}

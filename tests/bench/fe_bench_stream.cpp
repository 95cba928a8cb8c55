// The FusionEngine benchmark stream outside the benchmark, for comparing navfuse with Point One's
// own parser (fe_vendor_compare.sh) on the same bytes:
//   navfuse_fe_bench_stream write OUT [--signals]
//       writes navfuse_fe_bench's 200 MB, 1 %-corrupted stream (fusionengine_bench_stream.hpp);
//   navfuse_fe_bench_stream frame IN [--decode] [--runs N] [--chunk BYTES]
//       reads IN in chunks of BYTES (default 65536), as a link or file reader hands them over,
//       into the Framer alone or (--decode) the FusionEngineDecoder into a sink that counts
//       measurements, N times (default 1). Prints the valid frames per message type (framer
//       only: "type T N", the format fe_vendor_count.py prints), "frames N bad N", and
//       "median_s S mb_per_s R" (MB = 10^6 bytes), where the time runs from opening the file to
//       the end of the stream, in-process.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "tests/bench/fusionengine_bench_stream.hpp"

namespace {

using namespace navfuse;
using frontends::fusionengine::Frame;

int usage() {
  std::fprintf(stderr,
               "usage: navfuse_fe_bench_stream write OUT [--signals]\n"
               "       navfuse_fe_bench_stream frame IN [--decode] [--runs N] [--chunk BYTES]\n");
  return 2;
}

int write_stream(const std::string& path, bool with_signals) {
  const std::vector<std::uint8_t> bytes = bench::fe_bench_stream(0.01, with_signals, bench::kCorruptedStreamBytes);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    return 1;
  }
  std::printf("%zu bytes\n", bytes.size());
  return 0;
}

// Counts measurements only, as navfuse_fe_bench's sink does: asking for frame records would
// time building them too.
class CountingSink final : public frontends::DecodeSink {
 public:
  void on_measurement(const Measurement&) override { ++measurements; }
  std::uint64_t measurements = 0;
};

struct Pass {
  std::map<unsigned, std::uint64_t> by_type;  // framer only
  std::uint64_t bytes = 0, frames = 0, bad = 0, measurements = 0;
  double seconds = 0.0;
};

// One pass over the file: the chunked read is inside the timed span, as it is for the vendor's.
template <class Feed, class Finish>
bool read_in_chunks(const std::string& path, std::size_t chunk, Feed&& feed, Finish&& finish) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::vector<std::uint8_t> buf(chunk);
  while (in) {
    in.read(reinterpret_cast<char*>(buf.data()), static_cast<std::streamsize>(chunk));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got > 0) feed(std::span<const std::uint8_t>(buf.data(), got));
  }
  finish();
  return true;
}

bool frame_once(const std::string& path, std::size_t chunk, bool decode, Pass& pass) {
  const auto t0 = std::chrono::steady_clock::now();
  bool ok = false;
  if (decode) {
    frontends::fusionengine::FusionEngineDecoder decoder;
    CountingSink sink;
    ok = read_in_chunks(
        path, chunk, [&](std::span<const std::uint8_t> b) { decoder.feed(b, sink); }, [&] { decoder.finish(sink); });
    pass.bytes = decoder.counters().bytes;
    pass.frames = decoder.counters().frames;
    pass.bad = decoder.counters().bad_frames;
    pass.measurements = sink.measurements;
  } else {
    frontends::fusionengine::Framer framer;
    auto count = [&](const Frame& f) { ++pass.by_type[f.header.message_type]; };
    ok = read_in_chunks(
        path, chunk, [&](std::span<const std::uint8_t> b) { framer.feed(b, count); }, [&] { framer.finish(count); });
    pass.bytes = framer.counters().bytes;
    pass.frames = framer.counters().frames;
    pass.bad = framer.counters().bad_frames;
  }
  pass.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return ok;
}

int frame_file(const std::string& path, bool decode, int runs, std::size_t chunk) {
  std::vector<Pass> passes(static_cast<std::size_t>(runs));
  for (Pass& p : passes) {
    if (!frame_once(path, chunk, decode, p)) {
      std::fprintf(stderr, "cannot read %s\n", path.c_str());
      return 1;
    }
  }
  std::vector<double> times;
  for (const Pass& p : passes) times.push_back(p.seconds);
  std::sort(times.begin(), times.end());
  const double median = times[times.size() / 2];
  const Pass& p = passes.front();
  for (const auto& [type, n] : p.by_type) std::printf("type %u %llu\n", type, static_cast<unsigned long long>(n));
  std::printf("frames %llu bad %llu\n", static_cast<unsigned long long>(p.frames),
              static_cast<unsigned long long>(p.bad));
  if (decode) std::printf("measurements %llu\n", static_cast<unsigned long long>(p.measurements));
  std::printf("median_s %.4f mb_per_s %.1f\n", median, static_cast<double>(p.bytes) / median / 1e6);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string_view cmd = argv[1];
  const std::string path = argv[2];
  bool signals = false, decode = false;
  int runs = 1;
  std::size_t chunk = 65536;
  for (int i = 3; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "--signals") {
      signals = true;
    } else if (a == "--decode") {
      decode = true;
    } else if (a == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--chunk" && i + 1 < argc) {
      chunk = static_cast<std::size_t>(std::max(1L, std::atol(argv[++i])));
    } else {
      return usage();
    }
  }
  if (cmd == "write") return write_stream(path, signals);
  if (cmd == "frame") return frame_file(path, decode, runs, chunk);
  return usage();
}

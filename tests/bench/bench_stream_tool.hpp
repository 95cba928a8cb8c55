// The command line shared by the framing benchmarks' stream tools (navfuse_fe_bench_stream,
// navfuse_mip_bench_stream), which put a benchmark's corrupted stream outside the benchmark so a
// vendor's own parser can be timed on the same bytes (fe_vendor_compare.sh, mip_vendor_compare.sh):
//   TOOL write OUT [--signals]
//       writes the benchmark's 200 MB, 1 %-corrupted stream;
//   TOOL frame IN [--decode] [--runs N] [--chunk BYTES]
//       reads IN in chunks of BYTES (default 65536), as a link or file reader hands them over,
//       into the framer alone or (--decode) the decoder into a sink that counts measurements,
//       N times (default 1). Prints the valid frames per message type (framer only: "type T N",
//       the format the vendor drivers print), "frames N bad N", and "median_s S mb_per_s R"
//       (MB = 10^6 bytes), where the time runs from opening the file to the end of the stream,
//       in-process.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/measurements/measurements.hpp"
#include "frontends/common/stream_decoder.hpp"

namespace navfuse::bench {

// What one pass over the file found, and how long it took.
struct StreamPass {
  std::map<unsigned, std::uint64_t> by_type;  // framer only
  std::uint64_t bytes = 0, frames = 0, bad = 0, measurements = 0;
  double seconds = 0.0;
};

// Counts measurements only, as the benchmarks' sinks do: asking for frame records would time
// building them too.
class CountingSink final : public frontends::DecodeSink {
 public:
  void on_measurement(const Measurement&) override { ++measurements; }
  std::uint64_t measurements = 0;
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

// One pass of a protocol's framer (valid frames counted by `type_of(frame)`) or, with `decode`,
// of its decoder: the two have the same feed / finish / counters() shape in every front-end.
template <class Framer, class Decoder, class TypeOf>
bool frame_once_with(const std::string& path, std::size_t chunk, bool decode, StreamPass& pass, TypeOf type_of) {
  bool ok = false;
  if (decode) {
    Decoder decoder;
    CountingSink sink;
    ok = read_in_chunks(
        path, chunk, [&](std::span<const std::uint8_t> b) { decoder.feed(b, sink); }, [&] { decoder.finish(sink); });
    pass.measurements = sink.measurements;
    pass.bytes = decoder.counters().bytes;
    pass.frames = decoder.counters().frames;
    pass.bad = decoder.counters().bad_frames;
    return ok;
  }
  Framer framer;
  auto count = [&](const auto& frame) { ++pass.by_type[type_of(frame)]; };
  ok = read_in_chunks(
      path, chunk, [&](std::span<const std::uint8_t> b) { framer.feed(b, count); }, [&] { framer.finish(count); });
  pass.bytes = framer.counters().bytes;
  pass.frames = framer.counters().frames;
  pass.bad = framer.counters().bad_frames;
  return ok;
}

struct StreamTool {
  const char* name;
  // The stream (signals: FusionEngine's optional GNSSSignals messages; other tools ignore it).
  std::function<std::vector<std::uint8_t>(bool signals)> make_stream;
  // One timed pass (read_in_chunks inside): false when the file cannot be read.
  std::function<bool(const std::string& path, std::size_t chunk, bool decode, StreamPass& pass)> frame_once;
};

namespace detail {

inline int usage(const char* name) {
  std::fprintf(stderr,
               "usage: %s write OUT [--signals]\n"
               "       %s frame IN [--decode] [--runs N] [--chunk BYTES]\n",
               name, name);
  return 2;
}

inline int write_stream(const StreamTool& tool, const std::string& path, bool signals) {
  const std::vector<std::uint8_t> bytes = tool.make_stream(signals);
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

inline int frame_file(const StreamTool& tool, const std::string& path, bool decode, int runs, std::size_t chunk) {
  std::vector<StreamPass> passes(static_cast<std::size_t>(runs));
  for (StreamPass& p : passes) {
    const auto t0 = std::chrono::steady_clock::now();
    if (!tool.frame_once(path, chunk, decode, p)) {
      std::fprintf(stderr, "cannot read %s\n", path.c_str());
      return 1;
    }
    p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  std::vector<double> times;
  for (const StreamPass& p : passes) times.push_back(p.seconds);
  std::sort(times.begin(), times.end());
  const double median = times[times.size() / 2];
  const StreamPass& p = passes.front();
  for (const auto& [type, n] : p.by_type) std::printf("type %u %llu\n", type, static_cast<unsigned long long>(n));
  std::printf("frames %llu bad %llu\n", static_cast<unsigned long long>(p.frames),
              static_cast<unsigned long long>(p.bad));
  if (decode) std::printf("measurements %llu\n", static_cast<unsigned long long>(p.measurements));
  std::printf("median_s %.4f mb_per_s %.1f\n", median, static_cast<double>(p.bytes) / median / 1e6);
  return 0;
}

}  // namespace detail

inline int run_stream_tool(const StreamTool& tool, int argc, char** argv) {
  if (argc < 3) return detail::usage(tool.name);
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
      return detail::usage(tool.name);
    }
  }
  if (cmd == "write") return detail::write_stream(tool, path, signals);
  if (cmd == "frame") return detail::frame_file(tool, path, decode, runs, chunk);
  return detail::usage(tool.name);
}

}  // namespace navfuse::bench

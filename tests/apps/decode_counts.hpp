// Decodes a whole log file with a front-end and counts the measurements by kind: an independent
// read-back of what navfuse sim and the replay outputs wrote.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "frontends/common/frontend_info.hpp"
#include "test_files.hpp"

namespace navfuse::apps::testing {

struct DecodedLog {
  std::map<std::string, std::uint64_t> kinds;
  frontends::StreamCounters counters;
};

inline DecodedLog decode_file(const frontends::FrontendInfo& frontend, const std::filesystem::path& path) {
  struct Counter final : frontends::DecodeSink {
    std::map<std::string, std::uint64_t>* kinds = nullptr;
    void on_measurement(const Measurement& m) override { ++(*kinds)[std::string(to_string(kind_of(m)))]; }
  };
  DecodedLog out;
  Counter sink;
  sink.kinds = &out.kinds;
  auto decoder = frontend.make_decoder();
  const auto bytes = read_bytes(path);
  decoder->feed(bytes, sink);
  decoder->finish(sink);
  out.counters = decoder->counters();
  return out;
}

}  // namespace navfuse::apps::testing

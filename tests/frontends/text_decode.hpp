// Helpers for the text front-end tests (imutxt, rtklib): feed a string to a StreamDecoder whole
// or in small chunks and keep what comes out; read a file of ../shared when it exists.
#pragma once

#include <fstream>
#include <iterator>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends::test {

struct TextSink final : DecodeSink {
  std::vector<Measurement> measurements;
  std::vector<FrameRecord> records;
  void on_measurement(const Measurement& m) override { measurements.push_back(m); }
  void on_frame(const FrameRecord& r) override { records.push_back(r); }
  bool wants_frames() const override { return true; }
  template <class T>
  std::vector<T> all() const {
    std::vector<T> out;
    for (const auto& m : measurements) {
      if (const T* t = std::get_if<T>(&m)) out.push_back(*t);
    }
    return out;
  }
};

inline std::span<const std::uint8_t> bytes_of(std::string_view text) {
  return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

// Feeds `text` in chunks of `chunk` bytes (0: whole) and finishes.
inline TextSink decode_text(StreamDecoder& decoder, std::string_view text, std::size_t chunk = 0) {
  TextSink sink;
  const auto bytes = bytes_of(text);
  const std::size_t step = chunk == 0 ? std::max<std::size_t>(bytes.size(), 1) : chunk;
  for (std::size_t pos = 0; pos < bytes.size(); pos += step) {
    decoder.feed(bytes.subspan(pos, std::min(step, bytes.size() - pos)), sink);
  }
  decoder.finish(sink);
  return sink;
}

inline std::optional<std::string> read_shared(const std::string& relative) {
  std::ifstream in(std::string(NAVFUSE_SHARED_DIR) + "/" + relative, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline std::size_t count_lines(std::string_view text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n' ? 1 : 0;
  return n + (!text.empty() && text.back() != '\n' ? 1 : 0);
}

}  // namespace navfuse::frontends::test

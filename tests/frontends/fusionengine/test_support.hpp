// Helpers shared by the FusionEngine tests: a sink that keeps what it is given, hex parsing,
// and reading files from ../shared.
#pragma once

#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/message_catalog.hpp"
#include "frontends/fusionengine/payload_reader.hpp"
#include "frontends/fusionengine/writer.hpp"

namespace navfuse::frontends::fusionengine::test {

class CollectingSink : public frontends::DecodeSink {
 public:
  explicit CollectingSink(bool frames = false) : frames_(frames) {}
  void on_measurement(const Measurement& m) override { measurements.push_back(m); }
  void on_frame(const frontends::FrameRecord& r) override { records.push_back(r); }
  bool wants_frames() const override { return frames_; }

  std::size_t count(MeasurementKind kind) const {
    std::size_t n = 0;
    for (const auto& m : measurements) n += kind_of(m) == kind ? 1 : 0;
    return n;
  }
  template <class T>
  std::vector<T> all() const {
    std::vector<T> out;
    for (const auto& m : measurements)
      if (const T* t = std::get_if<T>(&m)) out.push_back(*t);
    return out;
  }
  // The value of field `name` in record `i` (nullopt when absent).
  std::optional<frontends::FieldValue> field(std::size_t i, std::string_view name) const {
    for (const auto& [k, v] : records.at(i).fields)
      if (k == name) return v;
    return std::nullopt;
  }

  std::vector<Measurement> measurements;
  std::vector<frontends::FrameRecord> records;

 private:
  bool frames_;
};

// "2e31 0000 ..." (xxd-style groups, as the digest prints them) -> bytes.
inline std::vector<std::uint8_t> from_hex(std::string_view text) {
  std::vector<std::uint8_t> out;
  int hi = -1;
  for (char c : text) {
    int v = -1;
    if (c >= '0' && c <= '9') v = c - '0';
    if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
    if (c >= 'A' && c <= 'F') v = c - 'A' + 10;
    if (v < 0) continue;
    if (hi < 0) {
      hi = v;
    } else {
      out.push_back(static_cast<std::uint8_t>(hi << 4 | v));
      hi = -1;
    }
  }
  return out;
}

inline std::optional<std::vector<std::uint8_t>> read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return std::nullopt;
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(f), {});
}

// Decodes a frame's payload with its catalogue layout and writes it again with the same header
// fields: the bytes must come back identical (nullopt for a type outside the catalogue or a
// payload too short for its layout).
inline std::optional<std::vector<std::uint8_t>> reencode(const Frame& f) {
  MessageSet set;
  FusionEngineWriter writer;
  std::optional<std::vector<std::uint8_t>> out;
  set.dispatch(f.header.message_type, [&](auto& msg) {
    if (!decode_payload(f.payload, msg)) return;
    std::vector<std::uint8_t> bytes;
    FrameOptions same = FrameOptions::with_source_id(f.header.source_id);
    same.message_version = f.header.message_version;
    same.sequence = f.header.sequence;
    writer.append(msg, bytes, same);
    out = std::move(bytes);
  });
  return out;
}

// All frames of a byte stream, copied out.
struct OwnedFrame {
  Header header;
  std::vector<std::uint8_t> bytes;
  Frame view() const {
    return {header, {bytes.data() + kHeaderSize, bytes.size() - kHeaderSize}, bytes, 0};
  }
};
inline std::vector<OwnedFrame> frames_of(std::span<const std::uint8_t> stream) {
  Framer framer;
  std::vector<OwnedFrame> out;
  auto keep = [&](const Frame& f) { out.push_back({f.header, {f.bytes.begin(), f.bytes.end()}}); };
  framer.feed(stream, keep);
  framer.finish(keep);
  return out;
}

}  // namespace navfuse::frontends::fusionengine::test

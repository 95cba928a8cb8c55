// Helpers shared by the VectorNav front-end tests.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/vectornav/decoder.hpp"

namespace navfuse::frontends::vectornav::test {

// "FA 01 08 00" -> bytes (spaces ignored).
inline std::vector<std::uint8_t> from_hex(std::string_view text) {
  std::vector<std::uint8_t> out;
  int hi = -1;
  for (char c : text) {
    int v = -1;
    if (c >= '0' && c <= '9') v = c - '0';
    else if (c >= 'A' && c <= 'F') v = c - 'A' + 10;
    else if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
    if (v < 0) continue;
    if (hi < 0) {
      hi = v;
    } else {
      out.push_back(static_cast<std::uint8_t>(hi * 16 + v));
      hi = -1;
    }
  }
  return out;
}

inline std::vector<std::uint8_t> text_bytes(std::string_view s) { return {s.begin(), s.end()}; }

class CollectingSink : public DecodeSink {
 public:
  explicit CollectingSink(bool frames = false) : frames_(frames) {}
  void on_measurement(const Measurement& m) override {
    measurements.push_back(m);
    ++by_kind[static_cast<std::size_t>(kind_of(m))];
  }
  void on_frame(const FrameRecord& r) override { records.push_back(r); }
  bool wants_frames() const override { return frames_; }
  std::size_t count(MeasurementKind k) const { return by_kind[static_cast<std::size_t>(k)]; }

  std::vector<Measurement> measurements;
  std::vector<FrameRecord> records;
  std::array<std::size_t, static_cast<std::size_t>(MeasurementKind::kCount)> by_kind{};

 private:
  bool frames_;
};

// Feeds `bytes` in one chunk and finishes.
inline void decode_all(VnStreamDecoder& d, const std::vector<std::uint8_t>& bytes, DecodeSink& sink) {
  d.feed(bytes, sink);
  d.finish(sink);
}

inline const FieldValue* field(const FrameRecord& r, std::string_view name) {
  for (const auto& [k, v] : r.fields)
    if (k == name) return &v;
  return nullptr;
}

}  // namespace navfuse::frontends::vectornav::test

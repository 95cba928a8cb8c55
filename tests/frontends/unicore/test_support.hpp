// Helpers shared by the UM220 tests: frame one sentence, collect decoder output.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/bytes/checks.hpp"
#include "frontends/common/stream_decoder.hpp"
#include "frontends/nmea/fields.hpp"
#include "frontends/nmea/framer.hpp"

namespace navfuse::frontends::unicore::test {

// Frames `sentence` + "\r\n"; the body and its fields, or nullopt if the framer rejects it.
struct Framed {
  std::string body;
  nmea::Fields fields;
};
inline std::optional<Framed> frame(const std::string& sentence) {
  nmea::SentenceFramer f;
  std::optional<Framed> out;
  const std::string line = sentence + "\r\n";
  f.feed(bytes::as_bytes(line), [&](const nmea::Frame& fr) { out = Framed{std::string(fr.body), {}}; });
  if (out) out->fields.split(out->body);
  return out;
}

// Encodes with `encode(m, out)` and strips "\r\n".
template <class T>
std::string reencode(const T& m) {
  std::vector<std::uint8_t> out;
  if (!encode(m, out)) return "<encode failed>";
  std::string text(out.begin(), out.end());
  return text.substr(0, text.size() - 2);
}

class CollectingSink : public frontends::DecodeSink {
 public:
  explicit CollectingSink(bool frames = false) : frames_(frames) {}
  void on_measurement(const Measurement& m) override { measurements.push_back(m); }
  void on_frame(const frontends::FrameRecord& r) override { records.push_back(r); }
  bool wants_frames() const override { return frames_; }
  std::size_t count(MeasurementKind k) const {
    std::size_t n = 0;
    for (const auto& m : measurements) n += kind_of(m) == k;
    return n;
  }
  std::vector<Measurement> measurements;
  std::vector<frontends::FrameRecord> records;

 private:
  bool frames_;
};

}  // namespace navfuse::frontends::unicore::test

// libFuzzer entry: the first byte picks a chunk size, the rest is fed to the FusionEngine
// StreamDecoder in chunks of that size. Invariants: every byte fed is counted; after finish()
// every byte is either inside a valid frame or skipped; unknown and undecodable frames are
// valid frames; measurements never outnumber what the frames can carry.
#include <cstdint>
#include <cstdlib>
#include <span>

#include "frontends/fusionengine/decoder.hpp"

namespace {

class CountingSink final : public navfuse::frontends::DecodeSink {
 public:
  void on_measurement(const navfuse::Measurement&) override { ++measurements; }
  void on_frame(const navfuse::frontends::FrameRecord& r) override { fields += r.fields.size(); }
  bool wants_frames() const override { return true; }
  std::uint64_t measurements = 0;
  std::uint64_t fields = 0;
};

void check(bool ok) {
  if (!ok) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t chunk = 1 + data[0];
  std::span<const std::uint8_t> bytes(data + 1, size - 1);
  navfuse::frontends::fusionengine::FusionEngineDecoder decoder;
  CountingSink sink;
  for (std::size_t at = 0; at < bytes.size(); at += chunk) {
    decoder.feed(bytes.subspan(at, std::min(chunk, bytes.size() - at)), sink);
  }
  decoder.finish(sink);
  const auto& c = decoder.counters();
  check(c.bytes == bytes.size());
  check(decoder.framer().buffered_bytes() == 0);
  check(decoder.framer().framed_bytes() + c.skipped_bytes == c.bytes);
  check(c.unknown_frames + c.decode_errors <= c.frames);
  // At most two measurements per frame (ROSGPSFix: position + velocity).
  check(sink.measurements <= 2 * c.frames);
  return 0;
}

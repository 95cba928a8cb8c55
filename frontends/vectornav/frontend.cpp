#include "frontends/vectornav/frontend.hpp"

#include "frontends/vectornav/decoder.hpp"
#include "frontends/vectornav/encoder.hpp"
#include "frontends/vectornav/framer.hpp"

namespace navfuse::frontends::vectornav {
namespace {
constexpr std::string_view kAsciiVectorNav = "$VN";
}

std::size_t probe_vectornav(std::span<const std::uint8_t> head) {
  PortFramer framer;
  std::size_t count = 0;
  auto on_frame = [&](const Frame& f) {
    if (f.kind != FrameKind::kAscii) {
      ++count;
      return;
    }
    const std::string_view text(reinterpret_cast<const char*>(f.bytes.data()), f.bytes.size());
    if (text.starts_with(kAsciiVectorNav)) ++count;
  };
  framer.feed(head, on_frame);
  return count;
}

const FrontendInfo& frontend() {
  static const FrontendInfo info{
      "vn",
      "VectorNav VN-300 binary (0xFA/0xFB) and ASCII ($VN) output",
      &probe_vectornav,
      []() -> std::unique_ptr<StreamDecoder> { return std::make_unique<VnStreamDecoder>(); },
      []() -> std::unique_ptr<MeasurementEncoder> { return std::make_unique<VnMeasurementEncoder>(); },
  };
  return info;
}

}  // namespace navfuse::frontends::vectornav

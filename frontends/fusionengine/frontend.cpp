#include "frontends/fusionengine/frontend.hpp"

#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/encoder.hpp"
#include "frontends/fusionengine/framer.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

std::size_t probe(std::span<const std::uint8_t> head) {
  Framer framer;
  std::size_t frames = 0;
  framer.feed(head, [&](const Frame&) { ++frames; });
  return frames;
}

std::unique_ptr<StreamDecoder> make_decoder() { return std::make_unique<FusionEngineDecoder>(); }
std::unique_ptr<MeasurementEncoder> make_encoder() { return std::make_unique<FusionEngineEncoder>(); }

}  // namespace

const FrontendInfo& frontend() {
  static const FrontendInfo info{"fe", "Point One FusionEngine binary (spec v0.24, protocol 1.25)", &probe,
                                 &make_decoder, &make_encoder};
  return info;
}

}  // namespace navfuse::frontends::fusionengine

#include "frontends/fusionengine/frontend.hpp"

#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/encoder.hpp"
#include "frontends/fusionengine/framer.hpp"

namespace navfuse::frontends {
namespace {

std::size_t probe(std::span<const std::uint8_t> head) {
  fe::Framer framer;
  std::size_t frames = 0;
  framer.feed(head, [&](const fe::Frame&) { ++frames; });
  return frames;
}

std::unique_ptr<StreamDecoder> make_decoder() { return std::make_unique<fe::FusionEngineDecoder>(); }
std::unique_ptr<MeasurementEncoder> make_encoder() { return std::make_unique<fe::FusionEngineEncoder>(); }

}  // namespace

const FrontendInfo& fusionengine_frontend() {
  static const FrontendInfo info{"fe", "Point One FusionEngine binary (spec v0.24, protocol 1.25)", &probe,
                                 &make_decoder, &make_encoder};
  return info;
}

}  // namespace navfuse::frontends

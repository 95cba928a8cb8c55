#include "frontends/mip/frontend.hpp"

#include "frontends/mip/decoder.hpp"
#include "frontends/mip/encoder.hpp"
#include "frontends/mip/framer.hpp"

namespace navfuse::frontends::mip {
namespace {

std::size_t probe(std::span<const std::uint8_t> head) {
  Framer framer;
  framer.feed(head, [](const PacketView&) {});
  return framer.counters().frames;
}

std::unique_ptr<StreamDecoder> make_decoder() { return std::make_unique<MipDecoder>(); }
std::unique_ptr<MeasurementEncoder> make_encoder() { return std::make_unique<MipEncoder>(); }

}  // namespace

const FrontendInfo& frontend() {
  static const FrontendInfo info{
      .format = "mip",
      .description = "MicroStrain MIP (3DM-CV7): sensor, filter, GNSS data and 0x13 aiding",
      .probe = &probe,
      .make_decoder = &make_decoder,
      .make_encoder = &make_encoder,
  };
  return info;
}

}  // namespace navfuse::frontends::mip

// The FusionEngine StreamDecoder (format "fe"): framer + typed decoding of every catalogue
// message + mapping into core measurements (to_core.hpp).
//
// Counters: frames / bad_frames / skipped_bytes come from the framer; a valid frame of a type
// the spec does not define is counted in unknown_frames (framed, named by its type id and
// skipped); a known type whose payload is shorter than its layout is a decode_error.
#pragma once

#include <optional>
#include <span>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/message_catalog.hpp"
#include "frontends/fusionengine/to_core.hpp"

namespace navfuse::frontends::fusionengine {

struct DecoderOptions {
  // WheelConfig the device was configured with, for tick rollover / direction (spec L1111-1172).
  // Without one, tick counters roll over at 2^32 and carry no direction; a SetConfig or
  // ConfigResponse with a WheelConfig in the stream replaces it.
  std::optional<WheelConfig> wheel_config;
};

class FusionEngineDecoder final : public frontends::StreamDecoder {
 public:
  explicit FusionEngineDecoder(const DecoderOptions& options = {});

  std::string_view format() const override { return "fe"; }
  void feed(std::span<const std::uint8_t> bytes, frontends::DecodeSink& sink) override;
  void finish(frontends::DecodeSink& sink) override;
  const frontends::StreamCounters& counters() const override { return framer_.counters(); }

  const Framer& framer() const { return framer_; }

 private:
  void on_frame(const Frame& frame, frontends::DecodeSink& sink);

  Framer framer_;
  MessageSet messages_;
  MeasurementMapper mapper_;
};

}  // namespace navfuse::frontends::fusionengine

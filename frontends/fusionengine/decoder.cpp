#include "frontends/fusionengine/decoder.hpp"

#include <string>

#include "frontends/fusionengine/message_versions.hpp"
#include "frontends/fusionengine/payload_reader.hpp"
#include "frontends/fusionengine/record_builder.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

constexpr std::string_view kProtocol = "fe";

frontends::FrameRecord record_head(const Frame& f, std::string name) {
  frontends::FrameRecord rec;
  rec.protocol = kProtocol;
  rec.name = std::move(name);
  rec.offset = f.offset;
  rec.fields.emplace_back("message_type", static_cast<std::uint64_t>(f.header.message_type));
  rec.fields.emplace_back("message_version", static_cast<std::uint64_t>(f.header.message_version));
  rec.fields.emplace_back("sequence", static_cast<std::uint64_t>(f.header.sequence));
  rec.fields.emplace_back("source_id", static_cast<std::uint64_t>(f.header.source_id));
  rec.fields.emplace_back("payload_bytes", static_cast<std::uint64_t>(f.header.payload_size));
  return rec;
}

}  // namespace

FusionEngineDecoder::FusionEngineDecoder(const DecoderOptions& options) {
  if (options.wheel_config) mapper_.set_wheel_config(*options.wheel_config);
}

void FusionEngineDecoder::feed(std::span<const std::uint8_t> bytes, frontends::DecodeSink& sink) {
  framer_.feed(bytes, [&](const Frame& f) { on_frame(f, sink); });
}

void FusionEngineDecoder::finish(frontends::DecodeSink& sink) {
  framer_.finish([&](const Frame& f) { on_frame(f, sink); });
  mapper_.flush(sink);
}

void FusionEngineDecoder::on_frame(const Frame& frame, frontends::DecodeSink& sink) {
  auto& counters = framer_.counters();
  const bool known = messages_.dispatch(frame.header.message_type, [&](auto& msg) {
    using M = std::decay_t<decltype(msg)>;
    const char* error = nullptr;
    if (!decode_payload(frame.payload, msg)) {
      error = "payload shorter than the message layout";
    } else if (!adapt_to_version(msg, frame.header.message_version)) {
      error = "message version without a layout in the spec";
    }
    if (error != nullptr) {
      ++counters.decode_errors;
      if (sink.wants_frames()) {
        auto rec = record_head(frame, std::string(M::kName));
        rec.fields.emplace_back("error", std::string(error));
        sink.on_frame(rec);
      }
      return;
    }
    if constexpr (requires { mapper_.on(msg, sink); }) mapper_.on(msg, sink);
    if (sink.wants_frames()) {
      auto rec = record_head(frame, std::string(M::kName));
      RecordBuilder builder(rec);
      msg.visit(builder);
      sink.on_frame(rec);
    }
  });
  if (!known) {
    ++counters.unknown_frames;
    if (sink.wants_frames()) {
      sink.on_frame(record_head(frame, "Unknown(" + std::to_string(frame.header.message_type) + ")"));
    }
  }
}

}  // namespace navfuse::frontends::fusionengine

// MipDecoder plumbing: framing, dispatch by descriptor set, aiding packets and FrameRecords.
#include "frontends/mip/decoder.hpp"

#include "core/rotation/rotation.hpp"
#include "frontends/mip/decoder_detail.hpp"
#include "frontends/mip/frame_record.hpp"

namespace navfuse::frontends::mip {

using namespace detail;

MipDecoder::MipDecoder(const DecoderOptions& options)
    : options_(options), clock_(options.clock), aiding_(&clock_), pending_(std::make_unique<PendingSolution>()) {
  last_time_source_.fill(TimeSource::kUnknown);
}

MipDecoder::~MipDecoder() = default;

void MipDecoder::feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) {
  framer_.feed(bytes, [this, &sink](const PacketView& p) { on_packet(p, sink); });
}

void MipDecoder::finish(DecodeSink& sink) {
  framer_.finish([this, &sink](const PacketView& p) { on_packet(p, sink); });
  flush_solution(sink);
}

void MipDecoder::on_packet(const PacketView& p, DecodeSink& sink) {
  if (sink.wants_frames()) emit_record(p, sink);
  switch (p.desc_set) {
    case set::kSensor: decode_sensor(p, sink); return;
    case set::kFilter: decode_filter(p, sink); return;
    case set::kGnss1: decode_gnss(p, options_.receiver_id_gnss1, sink); return;
    case set::kGnss2: decode_gnss(p, options_.receiver_id_gnss2, sink); return;
    case set::kGnssExternal: decode_gnss(p, options_.receiver_id_external, sink); return;
    case set::kAiding: decode_aiding(p, sink); return;
    case set::kGnssCorrections:
    case set::kSystem:
    case set::kBase:
    case set::k3dm:
    case set::kFilterCmd:
    case set::kGnssCmd:
      return;  // status and command traffic: framed and shown as records, no measurements
    default:
      ++framer_.counters().unknown_frames;
      return;
  }
}

void MipDecoder::decode_aiding(const PacketView& p, DecodeSink& sink) {
  AidingResult result;
  aiding_.handle_payload(p.payload, result);
  for (const auto& m : result.measurements) sink.on_measurement(m);
  for (const auto& c : result.codes)
    if (c.second != ReplyCode::kAck) {
      ++framer_.counters().decode_errors;  // a command the device would have NACKed
      break;
    }
}

void MipDecoder::emit_record(const PacketView& p, DecodeSink& sink) {
  FrameRecord rec;
  build_frame_record(p, rec);
  sink.on_frame(rec);
}

}  // namespace navfuse::frontends::mip

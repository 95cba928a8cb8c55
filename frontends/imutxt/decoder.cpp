#include "frontends/imutxt/decoder.hpp"

#include "core/time/gps_time.hpp"

namespace navfuse::frontends::imutxt {

void ImuTextDecoder::feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) {
  framer_.feed(bytes, [&](std::string_view line) { on_line(line, sink); });
}

void ImuTextDecoder::finish(DecodeSink& sink) {
  framer_.finish([&](std::string_view line) { on_line(line, sink); });
}

void ImuTextDecoder::on_line(std::string_view line, DecodeSink& sink) {
  const ParsedLine p = parse_line(line);
  switch (p.kind) {
    case LineKind::kBlank:
    case LineKind::kComment:
      framer_.skip_line(p.kind == LineKind::kBlank);
      return;
    case LineKind::kDamaged:
      framer_.reject_line();
      previous_ns_.reset();
      return;
    case LineKind::kData:
      break;
  }
  // Half a week backwards is the Sunday rollover, not a time step back.
  if (week_ && previous_tow_s_ && p.imu.tow_s < *previous_tow_s_ - 0.5 * time::kSecondsPerWeek) ++*week_;
  previous_tow_s_ = p.imu.tow_s;
  const std::int64_t t_ns = week_ ? time::gps_ns_from_week_tow(*week_, p.imu.tow_s) : time::nanoseconds(p.imu.tow_s);
  const double dt_s = previous_ns_ ? time::seconds(t_ns - *previous_ns_) : 0.0;
  previous_ns_ = t_ns;
  framer_.accept_line();
  if (sink.wants_frames()) sink.on_frame(to_record(p.imu, framer_.line_offset()));
  // A time that does not increase gives a negative or zero dt: passed on as 0 and left to the
  // engine's time checks (which reject and count a time going backwards).
  sink.on_measurement(to_core(p.imu, t_ns, week_ ? TimeSource::kGps : TimeSource::kUnknown, dt_s > 0.0 ? dt_s : 0.0));
}

}  // namespace navfuse::frontends::imutxt

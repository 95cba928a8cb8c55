// imutxt StreamDecoder (format "imutxt"): KF-GINS-style IMU text (to_core.hpp) -> ImuSample.
//
// Times: the file holds GPS seconds of week only; the week comes from outside (--gps-week, or the
// apps infer it from another GPS-timed input). With a week the samples are GPS-timed; without
// one they carry the bare seconds of week as TimeSource::kUnknown (fine for `decode`, never fused
// with GPS-timed inputs). A seconds-of-week value that drops by more than half a week continues
// in the next week (a log across the Sunday rollover).
//
// dt: the time since the previous good line. The first line, and the first after a damaged one,
// carry dt 0: their interval is unknown (the engine then times them from the sample times).
// A damaged line's increments are lost, so the following sample spans two intervals with one
// interval's increments; it is reported (bad_frames), not guessed.
// Counters: data lines are frames; comments / column headers unknown_frames; damaged lines
// (and overlong or binary ones) bad_frames.
#pragma once

#include <cstdint>
#include <optional>

#include "frontends/common/line_framer.hpp"
#include "frontends/common/stream_decoder.hpp"
#include "frontends/imutxt/to_core.hpp"

namespace navfuse::frontends::imutxt {

inline constexpr std::size_t kMaxLineBytes = 1024;

class ImuTextDecoder final : public StreamDecoder {
 public:
  explicit ImuTextDecoder(std::optional<std::int32_t> gps_week = std::nullopt) : week_(gps_week) {}
  std::string_view format() const override { return "imutxt"; }
  void feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) override;
  void finish(DecodeSink& sink) override;
  const StreamCounters& counters() const override { return framer_.counters(); }

 private:
  void on_line(std::string_view line, DecodeSink& sink);

  std::optional<std::int32_t> week_;
  LineFramer framer_{kMaxLineBytes};
  std::optional<double> previous_tow_s_;  // last good line (reset by a damaged line)
  std::optional<std::int64_t> previous_ns_;
};

}  // namespace navfuse::frontends::imutxt

// StreamDecoder for UM220-INS output streams (format "unicore"): frames sentences with
// nmea::SentenceFramer, decodes every output of the spec (GYOACC, GYOACC-V, SNRSTAT, NAVPOS,
// NAVVEL, NAVTIME, NAVACC, NAVATT, LSF, CWOUT, NOTICE, NMEA GGA/GLL/GSA/GSV/RMC/VTG/ZDA/GST in
// both dialects, command replies and configuration reports) and emits core measurements as
// described in to_core.hpp, on GPS time through UtcClock.
//
// Counters: `frames` counts every checksum-valid (or checksum-less) sentence; of those,
// `unknown_frames` are names this decoder does not know and `decode_errors` are known names whose
// fields did not parse. Measurements that cannot be emitted are counted in DropCounts by reason.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/nmea/framer.hpp"
#include "frontends/nmea/sentences.hpp"
#include "frontends/unicore/messages.hpp"
#include "frontends/unicore/utc_clock.hpp"

namespace navfuse::frontends::unicore {

struct DecoderOptions {
  nmea::FramerOptions framer;
  // Odometer pulse-to-metre scale. The UM220 calibrates its own and never reports it (digest §6);
  // when > 0 every GYOACC also yields a signed VehicleSpeed = pulses * scale / period.
  double odometer_m_per_pulse = 0.0;
  // Speed std given with those VehicleSpeed measurements (0: the configured wheel.speed_std_mps).
  double odometer_speed_std_mps = 0.0;
  // NAVACC and GST come after the NAVPOS/GGA they describe in the output order (CFGMSG ID order,
  // L352-L369), so a position takes the accuracy of the latest one no older than this.
  double accuracy_max_age_s = 1.5;
};

// Measurements not emitted, by reason.
struct DropCounts {
  std::uint64_t no_date = 0;          // time of day / week time before any full date was seen
  std::uint64_t no_time = 0;          // time field empty (receiver has not resolved UTC, L742)
  std::uint64_t unsupported_time_scale = 0;  // NAVPOS/NAVVEL on GLONASS time only
  std::uint64_t no_position = 0;      // NAVVEL before any NAVPOS (ECEF -> NED needs a position)
  std::uint64_t invalid_fix = 0;      // NAVPOS/NAVVEL quality 0 or 1 (invalid / external)
  std::uint64_t imu_not_aligned = 0;  // GYOACC-V with null IMU fields (L771)
};

class UnicoreDecoder final : public frontends::StreamDecoder {
 public:
  explicit UnicoreDecoder(DecoderOptions options = {});

  std::string_view format() const override { return "unicore"; }
  void feed(std::span<const std::uint8_t> bytes, frontends::DecodeSink& sink) override;
  void finish(frontends::DecodeSink& sink) override;
  const frontends::StreamCounters& counters() const override { return framer_.counters(); }

  const DropCounts& drops() const { return drops_; }
  const UtcClock& clock() const { return clock_; }
  // Dialect of the latest GSA/GSV/RMC (the sentences whose field count tells), h51 before any.
  nmea::Dialect dialect() const { return dialect_; }

 private:
  struct Timed {  // an accuracy message with its resolved time
    std::int64_t gps_ns = 0;
    bool valid = false;
  };

  void on_frame(const nmea::Frame& frame, frontends::DecodeSink& sink);
  void on_nmea(const nmea::Frame& frame, std::string_view type, frontends::DecodeSink& sink);
  void on_unicore(const nmea::Frame& frame, std::string_view name, frontends::DecodeSink& sink);
  // Emits a FrameRecord (when wanted) for a decoded message, or counts a decode error.
  template <class M>
  bool accept(const std::optional<M>& m, const nmea::Frame& frame, frontends::DecodeSink& sink);
  void record_generic(const nmea::Frame& frame, frontends::DecodeSink& sink);

  void emit_gyoacc(const Gyoacc& m, frontends::DecodeSink& sink);
  std::optional<std::int64_t> time_of_day(const std::optional<nmea::TimeOfDay>& tod);
  bool fresh(const Timed& t, std::int64_t gps_ns) const;

  DecoderOptions options_;
  nmea::SentenceFramer framer_;
  nmea::Fields fields_;
  std::array<char, 16> name_{};  // upper-cased sentence name of the current frame
  UtcClock clock_;
  DropCounts drops_;
  nmea::Dialect dialect_ = nmea::Dialect::kH51;

  std::optional<Navacc> navacc_;
  Timed navacc_time_;
  std::optional<nmea::Gst> gst_;
  Timed gst_time_;
  std::optional<Snrstat> snrstat_;
  std::optional<NavMode> gga_mode_;
  std::optional<std::pair<double, double>> last_lat_lon_rad_;
  std::uint32_t cumulative_pulses_ = 0;  // wraps at 2^32 (WheelTicks::rollover = 0)
};

}  // namespace navfuse::frontends::unicore

// MIP StreamDecoder (format "mip"): frames a CV7 byte stream and turns its data packets into
// core measurements (digest §4):
//   0x80 scaled accel/gyro (g -> m/s^2) or delta theta / delta velocity (g*s -> m/s) -> ImuSample,
//        scaled mag -> Magnetometer, scaled pressure (mbar -> Pa) -> Pressure,
//        odometer (0x80,0x40) -> VehicleSpeed;
//   0x91/0x92/0x94 LLH + fix info -> GnssPosition, NED velocity -> GnssVelocity;
//   0x82 filter fields -> NavSolution (kind device_solution), continuation packets merged;
//   (0x82,0x49) dual-antenna status -> GnssHeading;
//   0x13 aiding commands found in the stream -> External* measurements (through
//        AidingCommandHandler, so frame configurations in the stream are applied).
// Timestamps: (0xFF,0xD3) GPS time when valid (or the legacy (0x80,0x12)/(0x82,0x11)/(0x9x,0x09)
// GPS times); else (0xFF,0xD5) reference time mapped to GPS by a ClockModel fitted on packets
// that carry both; else the raw reference time flagged kDeviceMonotonic.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

#include "core/time/clock_model.hpp"
#include "frontends/common/stream_decoder.hpp"
#include "frontends/mip/aiding.hpp"
#include "frontends/mip/framer.hpp"

namespace navfuse::frontends::mip {

struct DecoderOptions {
  // receiver_id given to GnssPosition/GnssVelocity from each GNSS set.
  std::uint8_t receiver_id_gnss1 = 0;  // 0x91, internal receiver 1
  std::uint8_t receiver_id_gnss2 = 1;  // 0x92, internal receiver 2
  std::uint8_t receiver_id_external = 2;  // 0x94, external receiver via NMEA input
  time::ClockModel::Options clock{};      // reference-time -> GPS mapping
};

class MipDecoder final : public StreamDecoder {
 public:
  explicit MipDecoder(const DecoderOptions& options = {});
  ~MipDecoder() override;
  std::string_view format() const override { return "mip"; }
  void feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) override;
  void finish(DecodeSink& sink) override;
  const StreamCounters& counters() const override { return framer_.counters(); }
  // Decodes one already validated packet (used by feed(); public for tests and tools).
  void on_packet(const PacketView& packet, DecodeSink& sink);
  const time::ClockModel& clock() const { return clock_; }

 private:
  struct PacketTime;
  void decode_sensor(const PacketView& p, DecodeSink& sink);
  void decode_filter(const PacketView& p, DecodeSink& sink);
  void decode_gnss(const PacketView& p, std::uint8_t receiver_id, DecodeSink& sink);
  void decode_aiding(const PacketView& p, DecodeSink& sink);
  void flush_solution(DecodeSink& sink);
  void emit_record(const PacketView& p, DecodeSink& sink);

  DecoderOptions options_;
  Framer framer_;
  time::ClockModel clock_;
  AidingCommandHandler aiding_;
  // Last timestamp seen per data set, for packets that carry none (continuation packets, L3994).
  std::array<std::int64_t, 256> last_time_ns_{};
  std::array<TimeSource, 256> last_time_source_{};
  // 0x82 packets of one epoch are merged (continuation packets, L3974-3996).
  struct PendingSolution;
  std::unique_ptr<PendingSolution> pending_;
};

}  // namespace navfuse::frontends::mip

// MeasurementEncoder writing core measurements the way a UM220-INS emits them (for `navfuse sim`
// and round-trip tests); the inverse of to_core.hpp:
//   ImuSample (sensor frame)  -> GYOACC;  ImuSample (vehicle frame) -> GYOACC-V (RFU axes).
//                                Increments are divided by dt_s into rates.
//   WheelTicks / VehicleSpeed -> buffered (true, no bytes): their pulses ride in the next GYOACC
//                                (pulses since the previous GYOACC, period = time since it).
//                                VehicleSpeed needs odometer_m_per_pulse > 0, else false.
//   GnssPosition              -> NAVACC (when it has a covariance) + NAVPOS
//   GnssVelocity              -> NAVVEL (false before any GnssPosition: ECEF needs a position)
//   NavSolution               -> SNRSTAT (when device_status changed) + GST (position std) +
//                                GGA + NAVATT (when the attitude is valid)
// Before the first time-stamped sentence of each GPS second a NAVTIME is written (with GLONASS
// time, so the decoder learns GPS - UTC), as a real stream would carry it at 1 Hz.
// Other kinds return false. Number formats follow the spec's tables for the chosen dialect.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/nmea/talker.hpp"

namespace navfuse::frontends::unicore {

struct EncoderOptions {
  nmea::Dialect dialect = nmea::Dialect::kH51;  // CFGNMEA nmeaVer of the simulated device
  nmea::Talker talker{'G', 'N'};                // GGA talker: multi-system solution
  std::uint32_t navpos_system_mask = 0x5;       // NAVPOS/NAVVEL "system": GPS + BDS (L1288)
  double odometer_m_per_pulse = 0.0;            // to turn VehicleSpeed into pulses
  std::uint32_t default_imu_period_ms = 100;    // GYOACC period when ImuSample::dt_s is 0
  bool write_navtime = true;
};

class UnicoreEncoder final : public frontends::MeasurementEncoder {
 public:
  explicit UnicoreEncoder(EncoderOptions options = {}) : options_(options) {}
  bool encode(const Measurement& m, std::vector<std::uint8_t>& out) override;

 private:
  bool encode_imu(const ImuSample& s, std::vector<std::uint8_t>& out);
  bool encode_position(const GnssPosition& p, std::vector<std::uint8_t>& out);
  bool encode_velocity(const GnssVelocity& v, std::vector<std::uint8_t>& out);
  bool encode_solution(const NavSolution& s, std::vector<std::uint8_t>& out);
  void note_ticks(const WheelTicks& t);
  bool note_speed(const VehicleSpeed& v);
  void ensure_navtime(std::int64_t gps_ns, std::vector<std::uint8_t>& out);

  EncoderOptions options_;
  std::optional<std::int64_t> navtime_second_;
  // Odometer state between GYOACC sentences.
  bool have_odometer_ = false;
  std::uint32_t latest_ticks_ = 0;
  std::uint32_t ticks_at_last_gyoacc_ = 0;
  double pending_pulses_ = 0.0;  // from VehicleSpeed, fractional part carried
  std::optional<std::int64_t> last_speed_ns_;
  bool reverse_ = false;
  std::optional<std::int64_t> last_gyoacc_ns_;
  // Position for NAVVEL's NED -> ECEF rotation, velocity accuracy for NAVACC.
  std::optional<std::pair<double, double>> lat_lon_rad_;
  std::uint32_t vel_acc_mmps_ = 0;
  std::optional<std::uint32_t> last_status_;
};

}  // namespace navfuse::frontends::unicore

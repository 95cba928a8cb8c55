// Time tagging for one VN-300 stream (digest §5.2 and §11.8).
//
// GPS time (Time.TimeGps, or GpsTow + GpsWeek) is used when TimeStatus says the TOW is valid.
// Otherwise Time.TimeStartup (the MCU's +-20 ppm TCXO, L810-813) is mapped to GPS through a
// ClockModel fitted on the messages that carried both; before the first such pair the startup
// time is passed on as the device's monotonic clock. Frames that carry no time at all (most
// ASCII outputs, register replies) take the latest time seen on the stream.
#pragma once

#include <cstdint>
#include <optional>

#include "core/measurements/measurements.hpp"
#include "core/time/clock_model.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::frontends::vectornav {

struct Stamp {
  std::int64_t time_ns = 0;
  TimeSource source = TimeSource::kUnknown;
};

// Largest plausible device time: rejects uint64 fields that would wrap an int64 (year ~2126).
inline constexpr std::uint64_t kMaxPlausibleTimeNs = std::uint64_t{1} << 62;
// The same bound on a GPS week number (7624, year ~2126): larger weeks overflow ns arithmetic.
inline constexpr std::uint32_t kMaxPlausibleGpsWeek =
    static_cast<std::uint32_t>(kMaxPlausibleTimeNs / static_cast<std::uint64_t>(time::kNsPerWeek));

class StreamClock {
 public:
  // Stamp for a frame carrying `gps_ns` (already checked valid) and/or `startup_ns`.
  Stamp resolve(std::optional<std::int64_t> gps_ns, std::optional<std::int64_t> startup_ns);
  // Stamp for a frame without time: the latest one seen (kUnknown before any).
  Stamp latest() const { return latest_; }
  // Records a GPS time carried by a frame (e.g. an ASCII output's GpsTow/GpsWeek).
  void note_gps(std::int64_t gps_ns) { latest_ = {gps_ns, TimeSource::kGps}; }

 private:
  time::ClockModel clock_;
  Stamp latest_;
};

}  // namespace navfuse::frontends::vectornav

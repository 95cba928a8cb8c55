// Which measurements share the IMU stream's clock, so that the filter may fuse them.
//
// The filter fuses every measurement at its own timestamp on the IMU's time axis (DESIGN.md:
// "fused at the time they were taken"); a timestamp on another clock would be fused at a wrong
// time. Two clocks are the same when both are GPS time (whatever the device: each disciplines
// its clock to GPS), or when both are the same device's own clock, i.e. the same time source
// from the same input stream. Anything else is rejected with reason "time_base" until a mapping
// between the clocks exists; navfuse replay has none yet for logs from different devices.
// Kinds the filter does not fuse (filter/measurement_kinds.hpp: device solutions; magnetometer
// and pressure unless configured, Engine::fuses) pass through for counting.
// Only one IMU stream drives the filter: IMU samples of other inputs are rejected as
// "second_imu".
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "core/measurements/measurements.hpp"
#include "filter/measurement_kinds.hpp"

namespace navfuse::apps {

class TimeBaseGate {
 public:
  // nullopt: pass to the filter; otherwise the rejection reason. `fused`: whether the filter
  // fuses this kind with its configuration (Engine::fuses); the kind table's answer if not given.
  std::optional<std::string_view> check(const Measurement& m) { return check(m, filter::is_fused(kind_of(m))); }
  std::optional<std::string_view> check(const Measurement& m, bool fused) {
    const MeasurementHeader& h = header_of(m);
    const MeasurementKind kind = kind_of(m);
    if (kind == MeasurementKind::kImu) {
      if (imu_stream_ && *imu_stream_ != h.stream_id) return "second_imu";
      imu_stream_ = h.stream_id;
      imu_source_ = h.time_source;  // follows a device switching from its own clock to GPS
      return std::nullopt;
    }
    // Kinds the filter does not fuse pass through and are counted as ignored (the one list of
    // them is the filter's kind table).
    if (!fused || !imu_stream_) return std::nullopt;
    const bool same_clock = h.time_source == imu_source_ &&
                            (h.time_source == TimeSource::kGps || h.stream_id == *imu_stream_);
    if (same_clock) return std::nullopt;
    return "time_base";
  }

 private:
  std::optional<std::uint16_t> imu_stream_;
  TimeSource imu_source_ = TimeSource::kUnknown;
};

}  // namespace navfuse::apps

// Pose output decimation (config output.rate_hz; DESIGN.md: 0 = every IMU sample).
//
// A pose is due at the first IMU epoch at or after each multiple of the output period on the
// measurement time axis, so the output times depend only on the data (deterministic replays)
// and line up across runs and devices: with 200 Hz IMU and 100 Hz output, every second sample.
#pragma once

#include <cmath>
#include <cstdint>

namespace navfuse::apps {

class OutputRate {
 public:
  explicit OutputRate(double rate_hz)
      : period_ns_(rate_hz > 0.0 ? static_cast<std::int64_t>(std::llround(1e9 / rate_hz)) : 0) {}

  // True when a pose is due at `time_ns` (call once per IMU epoch, times increasing).
  bool due(std::int64_t time_ns) {
    if (period_ns_ <= 0) return true;
    const std::int64_t slot = floor_div(time_ns, period_ns_);
    if (have_slot_ && slot <= last_slot_) return false;
    have_slot_ = true;
    last_slot_ = slot;
    return true;
  }
  std::int64_t period_ns() const { return period_ns_; }

 private:
  static std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
  }
  std::int64_t period_ns_;
  std::int64_t last_slot_ = 0;
  bool have_slot_ = false;
};

}  // namespace navfuse::apps

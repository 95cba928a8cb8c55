// Simulated GNSS outages on a recorded log (`replay --gnss-outage PERIOD:DURATION[:START]`):
// how users measure dead-reckoning drift on real data, e.g. 10 s without GNSS every 30 s. The
// windows are laid on the measurement time axis from the first IMU sample: outage k covers
// [first + START + k PERIOD, first + START + k PERIOD + DURATION). GNSS position, velocity and
// heading inside a window are kept from the filter, counted as rejected "outage".
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace navfuse::apps {

struct GnssOutagePlan {
  double period_s = 0.0;
  double duration_s = 0.0;
  double start_s = 0.0;

  // "30:10" or "30:10:60"; nullopt with `error` set when malformed or not 0 < DURATION < PERIOD.
  static std::optional<GnssOutagePlan> parse(const std::string& text, std::string& error);

  // Whether `t_ns` lies in an outage, for a log whose first IMU sample is at `first_ns`.
  bool in_outage(std::int64_t t_ns, std::int64_t first_ns) const;
  // End of the outage window `t_ns` lies in (same axis), for scoring the drift at its end.
  std::int64_t outage_end_ns(std::int64_t t_ns, std::int64_t first_ns) const;
};

}  // namespace navfuse::apps

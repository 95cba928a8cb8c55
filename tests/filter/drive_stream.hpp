// A pre-generated measurement stream for throughput and allocation checks: the simulator's short
// drive with 200 Hz IMU, 10 Hz GNSS (position + velocity) and 10 Hz vehicle speed, in delivery
// order, cut after `seconds` of scenario time.
#pragma once

#include <vector>

#include "apps/sim/scenarios.hpp"
#include "apps/sim/simulator.hpp"
#include "filter/filter_options.hpp"
#include "tests/filter/scenario_harness.hpp"

namespace navfuse::filter::test {

struct DriveStream {
  std::vector<Measurement> measurements;
  std::size_t imu_samples = 0;
  FilterOptions options;
};

inline DriveStream make_drive_stream(double seconds) {
  sim::Scenario s = sim::make_scenario("drive_short");
  s.gnss.rate_hz = 10.0;
  s.gnss.outages.clear();
  s.wheel.rate_hz = 10.0;
  DriveStream out;
  out.options = options_for(s);
  sim::Simulator simulator(s);
  const std::int64_t end_ns = s.start_time_ns + static_cast<std::int64_t>(seconds * 1e9);
  Measurement m;
  while (simulator.next(m) && header_of(m).time_ns <= end_ns) {
    if (kind_of(m) == MeasurementKind::kImu) ++out.imu_samples;
    out.measurements.push_back(m);
  }
  return out;
}

}  // namespace navfuse::filter::test

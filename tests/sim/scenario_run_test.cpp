// Full-length named scenarios through the streaming API (label "scenario": ~seconds each).
#include <cmath>

#include <gtest/gtest.h>

#include "apps/sim/scenarios.hpp"
#include "apps/sim/simulator.hpp"

namespace navfuse::sim {
namespace {

TEST(ScenarioRun, DriveOutageStreamsTwentyMinutesWithTheOutageAndWheelSpeed) {
  const Scenario scenario = make_scenario("drive_outage");
  Simulator sim(scenario);
  Measurement m;
  std::int64_t imu = 0, gnss = 0, speed = 0, last_delivery = 0;
  double max_speed_error = 0.0;
  double max_stationary_speed = 0.0;
  while (sim.next(m)) {
    EXPECT_GE(sim.delivery_time_ns(), last_delivery);
    last_delivery = sim.delivery_time_ns();
    const double t = 1e-9 * static_cast<double>(header_of(m).time_ns - scenario.start_time_ns);
    switch (kind_of(m)) {
      case MeasurementKind::kImu:
        ++imu;
        break;
      case MeasurementKind::kGnssPosition:
        ++gnss;
        EXPECT_FALSE(t >= kDriveOutageStart_s && t < kDriveOutageStart_s + kDriveOutageDuration_s);
        break;
      case MeasurementKind::kVehicleSpeed: {
        ++speed;
        // Inside the outage the vehicle cruises at 20 m/s; the sensor reads 0.5 % high with
        // 5 cm/s noise (|error| < 6 sigma).
        const double v = std::get<VehicleSpeed>(m).speed_mps;
        if (t >= kDriveOutageStart_s + 1.0 && t < kDriveOutageStart_s + 30.0) {
          max_speed_error = std::max(max_speed_error, std::abs(v - 20.0 * 1.005));
        }
        if (t < 29.0) max_stationary_speed = std::max(max_stationary_speed, std::abs(v));
        break;
      }
      default:
        break;
    }
  }
  EXPECT_EQ(imu, 1200 * 200);
  EXPECT_EQ(gnss, 1200 * 5 + 1 - 120 * 5);
  EXPECT_EQ(speed, 1200 * 50 + 1);
  EXPECT_LT(max_speed_error, 0.3);
  EXPECT_EQ(max_stationary_speed, 0.0);
  // The drive ends standing still, at exactly start + 20 min.
  const TruthSample& end = sim.truth();
  EXPECT_TRUE(end.stationary);
  EXPECT_EQ(end.time_ns, scenario.start_time_ns + 1200LL * 1'000'000'000LL);
}

}  // namespace
}  // namespace navfuse::sim

// The simulator end to end: stream order and timing, latency, outages, determinism, truth CSV,
// named scenarios.
#include "apps/sim/simulator.hpp"

#include <cstring>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "apps/sim/scenarios.hpp"
#include "apps/sim/truth_csv.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

// A 60 s piece of the short drive (static start, acceleration, a turn) with every sensor on.
Scenario small(std::uint64_t seed = 1) {
  Scenario s = make_scenario("drive_short");
  s.seed = seed;
  s.trajectory.segments.resize(4);  // 30 s static, 10 s accelerate, 15 s cruise, 10 s turn
  s.gnss.outages = {{40.0, 45.0}};
  s.gnss.heading = true;
  s.gnss.secondary_lever_arm_m = {-0.7, -0.4, -1.3};
  s.wheel.wheel_speeds = true;
  return s;
}

TEST(Simulator, StreamIsInDeliveryOrderWithTheExpectedCounts) {
  const Scenario scenario = small();
  const SimulationOutput out = simulate(scenario);
  // 65 s at 200 Hz; 5 Hz GNSS at t = 0, 0.2, ..., 65.0 s (326 epochs, both ends included) minus
  // the 25 in the 5 s outage; 50 Hz wheel at 0, 0.02, ..., 65.0 s (3251).
  EXPECT_EQ(out.truth.size(), 13000u);
  std::size_t imu = 0, pos = 0, vel = 0, heading = 0, speed = 0, wheels = 0;
  std::int64_t last_delivery = 0, last_imu = scenario.start_time_ns;
  for (std::size_t i = 0; i < out.measurements.size(); ++i) {
    const Measurement& m = out.measurements[i];
    const std::int64_t stamp = header_of(m).time_ns;
    EXPECT_GE(out.delivery_time_ns[i], last_delivery);
    last_delivery = out.delivery_time_ns[i];
    EXPECT_EQ(out.delivery_time_ns[i], stamp);  // no latency configured
    EXPECT_EQ(header_of(m).time_source, TimeSource::kGps);
    switch (kind_of(m)) {
      case MeasurementKind::kImu:
        EXPECT_EQ(stamp, last_imu + 5'000'000);
        last_imu = stamp;
        EXPECT_EQ(out.truth[imu].time_ns, stamp);
        ++imu;
        break;
      case MeasurementKind::kGnssPosition: {
        ++pos;
        const double t = 1e-9 * static_cast<double>(stamp - scenario.start_time_ns);
        EXPECT_FALSE(t >= 40.0 && t < 45.0) << t;
        EXPECT_EQ(stamp % 200'000'000, 0);  // on the 5 Hz GPS-time grid
        break;
      }
      case MeasurementKind::kGnssVelocity: ++vel; break;
      case MeasurementKind::kGnssHeading: ++heading; break;
      case MeasurementKind::kVehicleSpeed: ++speed; break;
      case MeasurementKind::kWheelSpeed: ++wheels; break;
      default: ADD_FAILURE() << "unexpected kind"; break;
    }
  }
  EXPECT_EQ(imu, 13000u);
  EXPECT_EQ(pos, 326u - 25u);
  EXPECT_EQ(vel, pos);
  EXPECT_EQ(heading, pos);
  EXPECT_EQ(speed, 3251u);
  EXPECT_EQ(wheels, 3251u);
  // Truth flags follow the outage and the static start.
  const auto* in_outage = find_truth(out.truth, scenario.start_time_ns + 42'000'000'000LL);
  ASSERT_NE(in_outage, nullptr);
  EXPECT_FALSE(in_outage->gnss_available);
  EXPECT_TRUE(find_truth(out.truth, scenario.start_time_ns + 10'000'000'000LL)->stationary);
  EXPECT_TRUE(find_truth(out.truth, scenario.start_time_ns + 10'000'000'000LL)->gnss_available);
  EXPECT_FALSE(find_truth(out.truth, scenario.start_time_ns + 35'000'000'000LL)->stationary);
  EXPECT_EQ(find_truth(out.truth, scenario.start_time_ns), nullptr);
}

TEST(Simulator, LatencyDelaysDeliveryButNotTheStamp) {
  Scenario scenario = small();
  scenario.gnss.latency_s = 0.3;
  Simulator sim(scenario);
  Measurement m;
  std::int64_t last_imu = 0;
  int gnss = 0;
  while (sim.next(m)) {
    if (kind_of(m) == MeasurementKind::kImu) {
      last_imu = header_of(m).time_ns;
      EXPECT_EQ(sim.truth().time_ns, last_imu);
      continue;
    }
    if (kind_of(m) != MeasurementKind::kGnssPosition) continue;
    ++gnss;
    const std::int64_t stamp = header_of(m).time_ns;
    EXPECT_EQ(sim.delivery_time_ns(), stamp + 300'000'000);
    // Delivered with the IMU sample of stamp + 300 ms, before it (the fix is older).
    EXPECT_EQ(last_imu, stamp + 295'000'000);
    // The stamp is the true measurement time: position matches truth then, not at delivery.
    EXPECT_EQ(stamp % 200'000'000, 0);
  }
  // Fixes stamped after 64.7 s would arrive after the end (65 s): not delivered.
  EXPECT_EQ(gnss, 301 - 2);
}

TEST(Simulator, SameSeedSameOutputDifferentSeedDifferentOutput) {
  Scenario scenario = small(42);
  scenario.trajectory.segments.resize(2);  // 40 s is enough
  const SimulationOutput a = simulate(scenario);
  const SimulationOutput b = simulate(scenario);
  scenario.seed = 43;
  const SimulationOutput c = simulate(scenario);
  ASSERT_EQ(a.measurements.size(), b.measurements.size());
  ASSERT_EQ(a.measurements.size(), c.measurements.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.measurements.size(); ++i) {
    ASSERT_EQ(a.measurements[i].index(), b.measurements[i].index());
    if (const auto* x = std::get_if<ImuSample>(&a.measurements[i])) {
      const auto& y = std::get<ImuSample>(b.measurements[i]);
      EXPECT_EQ(std::memcmp(x->gyro.data(), y.gyro.data(), sizeof(double) * 3), 0);
      EXPECT_EQ(std::memcmp(x->accel.data(), y.accel.data(), sizeof(double) * 3), 0);
      if (std::get<ImuSample>(c.measurements[i]).gyro != x->gyro) ++differ;
    }
    if (const auto* x = std::get_if<GnssPosition>(&a.measurements[i])) {
      EXPECT_EQ(x->lat_rad, std::get<GnssPosition>(b.measurements[i]).lat_rad);
      EXPECT_NE(x->lat_rad, std::get<GnssPosition>(c.measurements[i]).lat_rad);
    }
  }
  EXPECT_EQ(differ, a.truth.size());
  // Truth does not depend on the seed; the biases do.
  EXPECT_EQ(a.truth.back().llh.lat_rad, c.truth.back().llh.lat_rad);
  EXPECT_NE(a.truth.back().gyro_bias_vehicle_rps, c.truth.back().gyro_bias_vehicle_rps);
}

TEST(Simulator, TruthCsvHasTheDocumentedColumns) {
  Scenario scenario = small();
  scenario.trajectory.segments.resize(1);
  scenario.trajectory.segments[0].duration_s = 0.01;
  const SimulationOutput out = simulate(scenario);
  ASSERT_EQ(out.truth.size(), 2u);
  std::ostringstream csv;
  write_truth_csv(csv, out.truth);
  std::istringstream in(csv.str());
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header,
            "time_gps_s,lat_deg,lon_deg,height_m,vn,ve,vd,roll_deg,pitch_deg,yaw_deg,stationary,"
            "gnss_available");
  // Start: GPS week 2300, TOW 302400 s; first sample 5 ms later. Start point 37.4275,
  // -122.1697 deg, 30 m, yaw 30 deg, at rest.
  EXPECT_EQ(row,
            "1391342400.005000000,37.4275000000,-122.1697000000,30.0000,0.00000,0.00000,0.00000,"
            "0.000000,0.000000,30.000000,1,1");
}

TEST(Scenarios, AllNamedScenariosAreWellFormed) {
  for (std::string_view name : scenario_names()) {
    const Scenario s = make_scenario(name);
    EXPECT_EQ(s.name, name);
    const Trajectory traj(s.trajectory, s.start_time_ns);
    EXPECT_GT(traj.duration_s(), 59.0) << name;
  }
  EXPECT_THROW(make_scenario("no_such_scenario"), std::invalid_argument);

  // drive_outage: 20 minutes, the outage is driven at 20 m/s, starting after a 30 s static start.
  const Scenario d = make_scenario("drive_outage");
  const Trajectory traj(d.trajectory, d.start_time_ns);
  EXPECT_DOUBLE_EQ(traj.duration_s(), 1200.0);
  ASSERT_EQ(d.gnss.outages.size(), 1u);
  for (double t = d.gnss.outages[0].start_s; t <= d.gnss.outages[0].end_s; t += 1.0) {
    EXPECT_DOUBLE_EQ(traj.kinematics(t).speed_mps, 20.0) << t;
  }
  EXPECT_TRUE(traj.kinematics(29.9).stationary);
  EXPECT_FALSE(traj.kinematics(30.5).stationary);
  EXPECT_DOUBLE_EQ(d.gnss.noise.horizontal_std_m, 1.5);
  EXPECT_EQ(d.gnss.lever_arm_m, Eigen::Vector3d(0.8, -0.4, -1.3));
  EXPECT_DOUBLE_EQ(d.imu.errors.gyro_arw_deg_rthr, 0.1);
  // drive_1h: three laps of it, an hour, drive_outage's outage in each lap, again at 20 m/s.
  const Scenario hour = make_scenario("drive_1h");
  const Trajectory hour_traj(hour.trajectory, hour.start_time_ns);
  EXPECT_DOUBLE_EQ(hour_traj.duration_s(), 3600.0);
  ASSERT_EQ(hour.gnss.outages.size(), 3u);
  for (const auto& outage : hour.gnss.outages) {
    EXPECT_DOUBLE_EQ(outage.end_s - outage.start_s, d.gnss.outages[0].end_s - d.gnss.outages[0].start_s);
    for (double t = outage.start_s; t <= outage.end_s; t += 1.0) {
      EXPECT_DOUBLE_EQ(hour_traj.kinematics(t).speed_mps, 20.0) << t;
    }
  }
  const Scenario rtk = make_scenario("rtk_drive");
  EXPECT_EQ(rtk.gnss.fix, GnssFixType::kRtkFixed);
  EXPECT_DOUBLE_EQ(rtk.gnss.rate_hz, 10.0);
  EXPECT_EQ(rtk.gnss.lever_arm_m, d.gnss.lever_arm_m);
}

}  // namespace
}  // namespace navfuse::sim

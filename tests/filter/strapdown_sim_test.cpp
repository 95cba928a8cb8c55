// The strapdown against the simulator's truth: a perfect IMU (no errors, no noise) over a drive
// with turns, accelerations and stops, integrated open loop (no GNSS, no filter) from the true
// state. In both increment conventions (ImuIncrements) the only errors left are the
// integration's own, ~1 mm over 190 s; a compensated increment taken for a raw one (what every
// VN-300 log got before the convention was carried) adds 0.5 dtheta x dv per interval and drifts
// by metres. Truth: apps/sim (trajectory from closed-form kinematics, IMU by Simpson quadrature).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "apps/sim/scenarios.hpp"
#include "apps/sim/simulator.hpp"
#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/strapdown.hpp"

namespace navfuse::filter {
namespace {

struct OpenLoopError {
  double horizontal_m = 0.0, speed_mps = 0.0, attitude_rad = 0.0;  // largest over the drive
};

// `as` overrides what the increments are said to contain (nullopt: what the simulator says).
OpenLoopError open_loop(ImuIncrements convention, std::optional<ImuIncrements> as = std::nullopt) {
  sim::Scenario s = sim::make_scenario("drive_short");
  s.imu.errors = sim::imu_error_spec(sim::ImuGrade::kPerfect);
  s.imu.convention = convention;
  s.gnss.enabled = false;
  s.wheel.vehicle_speed = false;
  sim::Simulator sim(s);
  Measurement m;
  NavState x;
  StrapdownMemory memory;
  bool started = false;
  OpenLoopError e;
  while (sim.next(m)) {
    if (kind_of(m) != MeasurementKind::kImu) continue;
    const ImuSample& imu = std::get<ImuSample>(m);
    const sim::TruthSample& t = sim.truth();
    if (!started) {
      x.time_ns = t.time_ns;
      x.lat_rad = t.llh.lat_rad;
      x.lon_rad = t.llh.lon_rad;
      x.height_m = t.llh.height_m;
      x.vel_ned_mps = t.vel_ned_mps;
      x.q_nb = t.q_nb;
      started = true;
      continue;
    }
    EXPECT_EQ(imu.increments, convention);
    const ImuIncrement inc{imu.header.time_ns, imu.dt_s, imu.gyro, imu.accel, as.value_or(imu.increments)};
    strapdown_step(x, memory, inc, LocalEarth::at(x.lat_rad, x.height_m));
    e.horizontal_m =
        std::max(e.horizontal_m, geo::ned_offset_m(t.llh, {x.lat_rad, x.lon_rad, x.height_m}).head<2>().norm());
    e.speed_mps = std::max(e.speed_mps, (x.vel_ned_mps - t.vel_ned_mps).norm());
    e.attitude_rad = std::max(e.attitude_rad, rot::rotvec_from_quat(t.q_nb * x.q_nb.conjugate()).norm());
  }
  return e;
}

void print(const char* what, const OpenLoopError& e) {
  std::printf("%s: largest horizontal error %.4f m, velocity %.2e m/s, attitude %.1e rad\n", what, e.horizontal_m,
              e.speed_mps, e.attitude_rad);
}

// Either convention, integrated as what it is: the integration's own error only.
void expect_follows_the_truth(ImuIncrements convention, const char* what) {
  const OpenLoopError e = open_loop(convention);
  print(what, e);
  EXPECT_LT(e.horizontal_m, 0.005);
  EXPECT_LT(e.speed_mps, 1e-4);
  EXPECT_LT(e.attitude_rad, 1e-7);
}

TEST(StrapdownAgainstSimulator, RawIntegralsFollowTheTruthOpenLoop) {
  expect_follows_the_truth(ImuIncrements::kRawIntegrals, "raw integrals");
}

TEST(StrapdownAgainstSimulator, CompensatedIncrementsFollowTheTruthOpenLoop) {
  expect_follows_the_truth(ImuIncrements::kCompensated, "compensated");
}

TEST(StrapdownAgainstSimulator, CompensatedIncrementsTakenForRawOnesDrift) {
  // The rotation term added twice: ~1.3 cm/s of velocity error per 90 deg turn at 15 m/s.
  const OpenLoopError e = open_loop(ImuIncrements::kCompensated, ImuIncrements::kRawIntegrals);
  print("compensated taken for raw", e);
  EXPECT_GT(e.horizontal_m, 1.0);
  EXPECT_GT(e.speed_mps, 0.01);
}

}  // namespace
}  // namespace navfuse::filter

// Where the calibration's epochs start (plan_epochs): the smoothed trajectory read at the time a
// pass's offset puts each IMU sample at, continuously in that offset.
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "calibration/calibration_epochs.hpp"

namespace navfuse::calib {
namespace {

constexpr std::int64_t kImuPeriod_ns = 10'000'000;  // 100 Hz, as the parking drive's IMU
constexpr double kJerk_mps3 = 0.2;                  // along north: a(t) = j t, v(t) = j t^2 / 2
constexpr double kLat0_rad = 0.6, kLon0_rad = -2.1;
constexpr double kEarthRadius_m = 6378137.0;

double seconds(std::int64_t ns) { return static_cast<double>(ns) * 1e-9; }

// A vehicle heading north with constant jerk, from rest at t = 0: IMU stamps every 10 ms for 20 s,
// a smoothed state at every stamp (the log's configured offset is 0, so the states are on the IMU
// clock as they are), GNSS fixes at 4 Hz.
CalibrationLog jerk_log() {
  CalibrationLog log;
  for (std::int64_t t = 0; t <= 20'000'000'000; t += kImuPeriod_ns) {
    ImuSample s;
    s.header.time_ns = t;
    s.quantity = ImuQuantity::kRates;
    s.dt_s = seconds(kImuPeriod_ns);
    s.accel = {kJerk_mps3 * seconds(t), 0.0, -9.8};
    log.imu.push_back(s);
    const double ts = seconds(t);
    TrajectoryPoint p;
    p.time_ns = t;
    p.lat_rad = kLat0_rad + kJerk_mps3 * ts * ts * ts / 6.0 / kEarthRadius_m;
    p.lon_rad = kLon0_rad;
    p.vel_ned_mps = {0.5 * kJerk_mps3 * ts * ts, 0.0, 0.0};
    log.trajectory.push_back(p);
  }
  for (std::int64_t t = 1'000'000'000; t <= 19'000'000'000; t += 250'000'000) {
    GnssPosition fix;
    fix.header.time_ns = t;
    log.positions.push_back(fix);
  }
  return log;
}

// Placed at offsets a fraction of a sample apart (the outer passes move it by such steps), each
// epoch starts from the state at its sample's stamp plus the offset, and its acceleration known
// is the trajectory's at that time: centred on it, not on the nearest sample. Read at the nearest
// samples the knowns' +-0.125 s window (12.5 samples here) ended midway between samples and its
// centre jumped by a whole sample (10 ms, here 2 mm/s^2) between offsets 2 ms apart.
TEST(CalibrationEpochs, StatesAndKnownsFollowTheOffsetContinuously) {
  const CalibrationLog log = jerk_log();
  const LocalFrame frame({kLat0_rad, kLon0_rad, 0.0});
  for (const double offset_s : {0.0, 0.0017, -0.0017, 0.0049, -0.0031}) {
    CalibrationSetup setup = log.setup;
    setup.imu_time_offset_s = offset_s;
    const EpochPlan plan = plan_epochs(log, setup, frame, 0.5, 0.1, 0.125);
    ASSERT_GT(plan.epochs.size(), 60u) << offset_s;
    for (const Epoch& e : plan.epochs) {
      const double t = seconds(e.time_ns) + offset_s;  // where this pass puts the sample
      if (t < 0.2 || t > 19.8) continue;               // the knowns' window inside the log
      const Eigen::Vector3d v(e.v[0], e.v[1], e.v[2]);
      EXPECT_NEAR(v.norm(), 0.5 * kJerk_mps3 * t * t, 1e-5) << "offset " << offset_s << " t " << t;
      // A central difference of a quadratic velocity is its derivative at the centre.
      EXPECT_NEAR(e.knowns.accel_t_mps2.norm(), kJerk_mps3 * t, 2e-5) << "offset " << offset_s << " t " << t;
    }
  }
}

// Off the trajectory's ends (and across a gap in it) nothing is made up: samples whose time has
// no smoothed state within 20 ms get no epoch.
TEST(CalibrationEpochs, NoEpochWhereTheTrajectoryDoesNotReach) {
  CalibrationLog log = jerk_log();
  // Keep the trajectory from 5 s to 15 s only.
  std::erase_if(log.trajectory, [](const TrajectoryPoint& p) {
    return p.time_ns < 5'000'000'000 || p.time_ns > 15'000'000'000;
  });
  const LocalFrame frame({kLat0_rad, kLon0_rad, 0.0});
  CalibrationSetup setup = log.setup;
  setup.imu_time_offset_s = 0.015;  // reads 15 ms later: within 20 ms of the last state still
  const EpochPlan plan = plan_epochs(log, setup, frame, 0.5, 0.1, 0.125);
  ASSERT_FALSE(plan.epochs.empty());
  for (const Epoch& e : plan.epochs) {
    const double t = seconds(e.time_ns) + 0.015;
    EXPECT_GE(t, 5.0 - 0.020);
    EXPECT_LE(t, 15.0 + 0.020);
  }
}

}  // namespace
}  // namespace navfuse::calib

// Odometry fused at the covariance grid (measurement_kinds.hpp, FuseTime::kCovarianceGrid): the
// speed model's shift over the time between the speed and the state (wheel_speed.hpp), checked
// in closed form, and the Engine's timing: a speed between grid points costs no covariance step,
// and one that arrives late but inside its step needs no re-propagation.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"
#include "filter/measurements/wheel_speed.hpp"
#include "filter/measurements/wheel_ticks.hpp"
#include "tests/filter/line_trajectory.hpp"

namespace navfuse::filter {
namespace {

constexpr double kLat = 45.0 * rot::kDegToRad;

// Specific force that gives body-frame kinematic acceleration `accel_b` (d v_n / dt rotated into
// the body) at attitude `rpy`: f = C_bn (a_n - g_n).
Eigen::Vector3d force_for(const Eigen::Vector3d& accel_b, const Eigen::Vector3d& rpy, const LocalEarth& earth) {
  return accel_b - rot::dcm_from_rpy(rpy).transpose() * earth.gravity_ned_mps2;
}

TEST(OdometryShift, ForwardAccelerationOnASlope) {
  // Accelerating at 1.5 m/s^2 up a 5 deg slope, heading 30 deg, no rotation: the specific force's
  // forward part is 1.5 m/s^2 plus g sin(5 deg); the point accelerates at 1.5 m/s^2.
  const LocalEarth earth = LocalEarth::at(kLat, 100.0);
  NavState x;
  x.lat_rad = kLat;
  x.height_m = 100.0;
  const Eigen::Vector3d rpy = Eigen::Vector3d(0.0, 5.0, 30.0) * rot::kDegToRad;
  x.q_nb = rot::quat_from_rpy(rpy);
  x.vel_ned_mps = rot::dcm_from_rpy(rpy) * Eigen::Vector3d(10.0, 0.0, 0.0);
  const StateView view(x, earth, Eigen::Vector3d::Zero(), 0.0);
  const Eigen::Vector3d force = force_for({1.5, 0.0, 0.0}, rpy, earth);
  // (Normal gravity's few 1e-6 g of north component, turned by the heading, aside.)
  EXPECT_NEAR(force.x(), 1.5 + earth.gravity_ned_mps2.z() * std::sin(5.0 * rot::kDegToRad), 1e-5);
  EXPECT_NEAR(forward_accel_mps2(view, force), 1.5, 1e-9);
}

TEST(OdometryShift, ForwardAccelerationInASteadyTurnIsZero) {
  // A steady 0.5 rad/s turn at 8 m/s, the IMU 1.2 m ahead of a rear axle that does not slip: the
  // IMU moves sideways at 0.5 x 1.2 = 0.6 m/s, and its body-frame velocity is constant, so the
  // specific force is w x v_b - C_bn g, whose forward part (w x v_b)_x = -w_z v_y = -0.3 m/s^2
  // is no change of the axle's speed. Without the -w x v_b term the model would take it for one.
  const LocalEarth earth = LocalEarth::at(kLat, 100.0);
  NavState x;
  x.lat_rad = kLat;
  x.height_m = 100.0;
  const Eigen::Vector3d rpy(0.0, 0.0, 1.0);
  x.q_nb = rot::quat_from_rpy(rpy);
  const Eigen::Vector3d v_b(8.0, 0.6, 0.0);
  x.vel_ned_mps = rot::dcm_from_rpy(rpy) * v_b;
  const Eigen::Vector3d w(0.0, 0.0, 0.5);
  const StateView view(x, earth, w, 0.0);
  const Eigen::Vector3d force = force_for(w.cross(v_b), rpy, earth);
  EXPECT_NEAR(force.x() + (rot::dcm_from_rpy(rpy).transpose() * earth.gravity_ned_mps2).x(), -0.3, 1e-12);
  EXPECT_NEAR(forward_accel_mps2(view, force), 0.0, 1e-12);
  // The axle's speed: 8 m/s (its lateral speed is zero: 0.6 - 0.5 x 1.2), whatever the shift.
  const Eigen::Vector3d axle(-1.2, 0.0, 0.0);
  const SpeedReading reading{8.0, 0.05};
  for (const double shift : {0.0, -0.04}) {
    const StateView shifted(x, earth, w, shift);
    const Observation obs = wheel_speed_observation(shifted, reading, axle, forward_accel_mps2(shifted, force));
    // w_eb = w - C_bn w_ie: the earth rate's 7e-5 rad/s times the 1.2 m lever.
    EXPECT_NEAR(obs.residual(0), 0.0, 2e-4) << "shift " << shift;
  }
}

TEST(OdometryShift, SpeedAndTicksAreMovedBackToTheirTime) {
  // State at t, 10 m/s forward, accelerating at 1.5 m/s^2; the speed was 9.94 m/s at t - 40 ms
  // (one covariance step back). Modelled, the residual vanishes; unshifted it is the 6 cm/s the
  // acceleration made.
  const LocalEarth earth = LocalEarth::at(kLat, 0.0);
  NavState x;
  x.lat_rad = kLat;
  x.vel_ned_mps = {10.0, 0.0, 0.0};
  const Eigen::Vector3d force = force_for({1.5, 0.0, 0.0}, Eigen::Vector3d::Zero(), earth);
  const SpeedReading reading{9.94, 0.05};
  const StateView at_speed(x, earth, Eigen::Vector3d::Zero(), -0.04);
  const double a = forward_accel_mps2(at_speed, force);
  EXPECT_NEAR(wheel_speed_observation(at_speed, reading, Eigen::Vector3d::Zero(), a).residual(0), 0.0, 1e-12);
  const StateView unshifted(x, earth, Eigen::Vector3d::Zero(), 0.0);
  EXPECT_NEAR(wheel_speed_observation(unshifted, reading, Eigen::Vector3d::Zero(), a).residual(0), 0.06, 1e-12);
  // Ticks over the 100 ms before t - 40 ms: the mean speed is the speed at t - 90 ms, 9.865 m/s.
  const TickSpeed ticks{{9.865, 0.05}, 0.1};
  EXPECT_NEAR(wheel_tick_observation(at_speed, ticks, Eigen::Vector3d::Zero(), a).residual(0), 0.0, 1e-12);
  // The scale factor's column is the shifted speed: (1 + k) s, d/dk = s.
  EXPECT_NEAR(wheel_speed_observation(at_speed, reading, Eigen::Vector3d::Zero(), a).h(0, sx::kWheelScale), 9.94,
              1e-12);
}

// 10 m/s north on a line, heading configured, 5 Hz fixes on the covariance grid and a vehicle
// speed at 40 Hz stamped on IMU samples that never fall on the 50 ms grid (k = 3, 8, 13, ... of
// the 200 Hz samples; the grid ends at k = 10, 20, ...).
struct DriveItem {
  Measurement m;
  int imu_index;  // the IMU sample it is stamped at (IMU samples: their own index)
};

std::vector<DriveItem> drive(double seconds) {
  test::LineTrajectory traj({kLat, 0.1, 200.0}, Eigen::Vector3d(10.0, 0.0, 0.0), Eigen::Vector3d::Zero(), 200.0);
  std::mt19937_64 rng(7);
  std::vector<DriveItem> out;
  const int n = static_cast<int>(seconds * 200.0);
  for (int k = 1; k <= n; ++k) {
    out.push_back({traj.next(), k});
    if (k % 40 == 0) {
      out.push_back({test::make_fix(traj.truth(), Eigen::Vector3d::Zero(), 0.5, &rng), k});
      out.push_back({test::make_velocity(traj.truth(), 0.05, &rng), k});
    }
    if (k % 5 == 3) {
      VehicleSpeed s;
      s.header.time_ns = traj.truth().time_ns;
      s.header.valid = VehicleSpeed::kValidSpeed;
      s.speed_mps = 10.0;
      s.gear = Gear::kForward;
      out.push_back({s, k});
    }
  }
  return out;
}

FilterOptions heading_north() {
  FilterOptions o;
  o.initial_heading_rad = 0.0;
  return o;
}

// From this IMU sample on the filter navigates (levelled, heading and position known).
constexpr int kSettledSample = 5 * 200;

TEST(OdometryTiming, SpeedsBetweenGridPointsCostNoCovarianceStep) {
  Engine e{heading_north()};
  std::set<std::int64_t> steps_ns;  // the times the covariance was propagated to, once settled
  const std::int64_t grid_ns = std::llround(e.options().covariance_interval_s * 1e9);
  for (const DriveItem& item : drive(20.0)) {
    e.process(item.m);
    if (item.imu_index > kSettledSample) {
      ASSERT_TRUE(e.solution_valid());
      steps_ns.insert(e.core().covariance_time_ns);
    }
  }
  ASSERT_EQ(e.solution().mode, NavMode::kNavigation);
  const std::uint64_t used = e.used(MeasurementKind::kVehicleSpeed);
  EXPECT_GT(used, 700u);  // of 800, the first before the heading was levelled in
  // Every step ends on the grid: 20 a second (the speeds at 40 Hz would add 40 a second).
  for (const std::int64_t t : steps_ns) EXPECT_EQ(t % grid_ns, 0) << t;
  const double navigating_s = static_cast<double>(*steps_ns.rbegin() - *steps_ns.begin()) * 1e-9;
  EXPECT_NEAR(static_cast<double>(steps_ns.size()), navigating_s / 0.05 + 1.0, 1.0);
  // The speeds, noise-free, hold the velocity.
  EXPECT_LT((e.solution().vel_ned_mps - Eigen::Vector3d(10.0, 0.0, 0.0)).norm(), 0.02);
}

TEST(OdometryTiming, ASpeedLateInsideItsStepNeedsNoReplay) {
  // Once navigating, the speeds delivered one IMU sample late (5 ms, within the open covariance
  // step): fused at the same grid point with the same shift as in time, so the result is the same
  // to the bit and nothing is re-propagated. (Before the filter is levelled there is no step to
  // wait for, and a late speed is re-propagated as any late measurement is.)
  const std::vector<DriveItem> items = drive(20.0);
  std::vector<Measurement> in_time, late;
  std::vector<Measurement> held;
  for (const DriveItem& item : items) {
    in_time.push_back(item.m);
    if (kind_of(item.m) == MeasurementKind::kVehicleSpeed && item.imu_index > kSettledSample) {
      held.push_back(item.m);
      continue;
    }
    late.push_back(item.m);
    if (kind_of(item.m) == MeasurementKind::kImu) {
      // The speeds stamped at the previous sample.
      for (const Measurement& m : held) {
        if (header_of(m).time_ns < header_of(item.m).time_ns) late.push_back(m);
      }
      std::erase_if(held, [&](const Measurement& m) { return header_of(m).time_ns < header_of(item.m).time_ns; });
    }
  }
  Engine a{heading_north()};
  Engine b{heading_north()};
  for (const Measurement& m : in_time) a.process(m);
  for (const Measurement& m : late) b.process(m);
  EXPECT_EQ(b.stats().replays, 0u);
  EXPECT_EQ(b.used(MeasurementKind::kVehicleSpeed), a.used(MeasurementKind::kVehicleSpeed));
  EXPECT_EQ(a.solution().lat_rad, b.solution().lat_rad);
  EXPECT_EQ(a.solution().vel_ned_mps, b.solution().vel_ned_mps);
  EXPECT_EQ(a.solution().vel_std_ned_mps, b.solution().vel_std_ned_mps);
}

}  // namespace
}  // namespace navfuse::filter

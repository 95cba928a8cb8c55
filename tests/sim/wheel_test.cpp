// Wheel odometry model: scale error and noise statistics, exact zero at rest, lever-arm geometry
// of the speed point and of the four wheels in a turn.
#include "apps/sim/wheel_model.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

constexpr double kDeg = rot::kDegToRad;

// Level vehicle heading north at `speed`, yawing at `yaw_rate` (earth rate included so that
// omega_eb is exactly the yaw rate).
TruthSample driving(double speed, double yaw_rate) {
  TruthSample t;
  t.llh = {47.0 * kDeg, 8.0 * kDeg, 400.0};
  t.vel_ned_mps = {speed, 0.0, 0.0};
  t.speed_mps = speed;
  t.omega_ib_b_rps = geo::earth_rate_ned(t.llh.lat_rad) + Eigen::Vector3d(0.0, 0.0, yaw_rate);
  t.stationary = speed == 0.0 && yaw_rate == 0.0;
  return t;
}

TEST(WheelModel, ScaleErrorAndNoiseStatistics) {
  // 20000 samples at 20 m/s: mean 20 (1 + k) within 3 sigma/sqrt(N) = 1e-3, std within ~2 %.
  WheelSpec spec;
  spec.vehicle_speed = true;
  spec.scale_error = 0.01;
  spec.noise_std_mps = 0.05;
  WheelModel model(spec, 5);
  const TruthSample t = driving(20.0, 0.0);
  double sum = 0.0, ss = 0.0;
  const int n = 20000;
  VehicleSpeed out;
  for (int i = 0; i < n; ++i) {
    model.make_vehicle_speed(t, out);
    sum += out.speed_mps;
    ss += out.speed_mps * out.speed_mps;
  }
  const double mean = sum / n, sd = std::sqrt(ss / n - mean * mean);
  EXPECT_NEAR(mean, 20.2, 1.1e-3);
  EXPECT_NEAR(sd / 0.05, 1.0, 0.03);
  EXPECT_EQ(out.gear, Gear::kForward);
  EXPECT_TRUE(out.is_signed);
  EXPECT_DOUBLE_EQ(out.speed_std_mps, 0.05);
  EXPECT_EQ(out.header.valid, VehicleSpeed::kValidSpeed);
}

TEST(WheelModel, ExactlyZeroAtRestAndReverseKeepsItsSign) {
  WheelSpec spec;
  spec.vehicle_speed = true;
  spec.wheel_speeds = true;
  WheelModel model(spec, 5);
  VehicleSpeed vs;
  WheelSpeeds ws;
  model.make_vehicle_speed(driving(0.0, 0.0), vs);
  model.make_wheel_speeds(driving(0.0, 0.0), ws);
  EXPECT_EQ(vs.speed_mps, 0.0);
  for (double w : ws.speed_mps) EXPECT_EQ(w, 0.0);
  model.make_vehicle_speed(driving(-3.0, 0.0), vs);
  EXPECT_LT(vs.speed_mps, -2.5);
  EXPECT_EQ(vs.gear, Gear::kReverse);
  model.make_vehicle_speed(driving(0.0, 0.0), vs);
  EXPECT_EQ(vs.gear, Gear::kReverse);  // a stop keeps the last gear
}

TEST(WheelModel, WheelSpeedsFollowTheTurnGeometry) {
  // Right turn (yaw rate r > 0) at u = 10 m/s about the reference point; rear axle centre at
  // l = (-1.2, 0, 0.3). A contact point at (x, y) moves at (u - r y, r x) in the body frame (by
  // hand: omega x l = (-r y, r x, 0)); the outer (left) wheels are faster.
  WheelSpec spec;
  spec.vehicle_speed = true;
  spec.wheel_speeds = true;
  spec.noise_std_mps = 0.0;
  spec.lever_arm_m = {-1.2, 0.0, 0.3};
  spec.track_m = 1.6;
  spec.wheelbase_m = 2.8;
  WheelModel model(spec, 1);
  const double u = 10.0, r = 0.3;
  const TruthSample t = driving(u, r);
  VehicleSpeed vs;
  WheelSpeeds ws;
  model.make_vehicle_speed(t, vs);
  model.make_wheel_speeds(t, ws);
  EXPECT_NEAR(vs.speed_mps, u, 1e-9);  // the rear-axle centre is on the body x axis
  auto wheel = [&](double x, double y) { return std::hypot(u - r * y, r * x); };
  EXPECT_NEAR(ws.speed_mps[0], wheel(1.6, -0.8), 1e-9);   // front left
  EXPECT_NEAR(ws.speed_mps[1], wheel(1.6, 0.8), 1e-9);    // front right
  EXPECT_NEAR(ws.speed_mps[2], wheel(-1.2, -0.8), 1e-9);  // rear left
  EXPECT_NEAR(ws.speed_mps[3], wheel(-1.2, 0.8), 1e-9);   // rear right
  EXPECT_GT(ws.speed_mps[2], ws.speed_mps[3]);
}

}  // namespace
}  // namespace navfuse::sim

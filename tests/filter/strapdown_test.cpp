// Strapdown mechanisation against closed-form motion (line_trajectory.hpp): standing still at a
// latitude, cruising at constant velocity, spinning in place, and rates vs increments input.
#include <gtest/gtest.h>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/imu_input.hpp"
#include "filter/strapdown.hpp"
#include "tests/filter/line_trajectory.hpp"

namespace navfuse::filter {
namespace {

struct Mechanisation {
  NavState x;
  StrapdownMemory memory;
};

Mechanisation start_at(const test::LineTruth& t) {
  Mechanisation r;
  r.x.time_ns = t.time_ns;
  r.x.lat_rad = t.llh.lat_rad;
  r.x.lon_rad = t.llh.lon_rad;
  r.x.height_m = t.llh.height_m;
  r.x.vel_ned_mps = t.vel_ned_mps;
  r.x.q_nb = rot::quat_from_rpy(t.rpy_rad);
  return r;
}

void step(Mechanisation& r, const ImuSample& s) {
  const ImuIncrement inc{s.header.time_ns, s.dt_s, s.gyro, s.accel};
  strapdown_step(r.x, r.memory, compensate(inc, r.x), LocalEarth::at(r.x.lat_rad, r.x.height_m));
}

double position_error_m(const Mechanisation& r, const test::LineTruth& t) {
  return geo::ned_offset_m(t.llh, {r.x.lat_rad, r.x.lon_rad, r.x.height_m}).norm();
}

double attitude_error_rad(const Mechanisation& r, const test::LineTruth& t) {
  return rot::rotvec_from_quat(rot::quat_from_rpy(t.rpy_rad).conjugate() * r.x.q_nb).norm();
}

TEST(Strapdown, StaticAtLatitudeStaysPut) {
  // Standing still at 45 deg N for 10 minutes: gravity, earth rate and Coriolis must cancel
  // exactly; any error in g, w_ie or the frame rotation shows as velocity growing linearly.
  test::LineTrajectory traj({45.0 * rot::kDegToRad, 7.0 * rot::kDegToRad, 120.0}, Eigen::Vector3d::Zero(),
                            Eigen::Vector3d(2.0, -3.0, 30.0) * rot::kDegToRad, 200.0);
  Mechanisation r = start_at(traj.truth());
  for (int k = 0; k < 200 * 600; ++k) step(r, traj.next());
  EXPECT_LT(r.x.vel_ned_mps.norm(), 1e-3);
  EXPECT_LT(position_error_m(r, traj.truth()), 0.2);
  EXPECT_LT(attitude_error_rad(r, traj.truth()), 1e-6);
}

TEST(Strapdown, ConstantVelocityAtHighLatitude) {
  // 20 m/s north-east at 60 deg N for 5 minutes: the transport rate and Coriolis terms matter
  // (w_en ~ 3e-6 rad/s, 2 w_ie x v ~ 3e-3 m/s^2).
  const Eigen::Vector3d v(14.0, 14.0, -0.5);
  test::LineTrajectory traj({60.0 * rot::kDegToRad, 10.0 * rot::kDegToRad, 50.0}, v,
                            Eigen::Vector3d(0.0, 0.0, 45.0) * rot::kDegToRad, 200.0);
  Mechanisation r = start_at(traj.truth());
  for (int k = 0; k < 200 * 300; ++k) step(r, traj.next());
  EXPECT_LT((r.x.vel_ned_mps - v).norm(), 1e-3);
  EXPECT_LT(position_error_m(r, traj.truth()), 0.1);
  EXPECT_LT(attitude_error_rad(r, traj.truth()), 1e-6);
}

TEST(Strapdown, SpinInPlaceTracksYaw) {
  // One full turn every 10 s for 60 s, tilted 5 deg: the yaw must follow and the tilt stay.
  test::LineTrajectory traj({30.0 * rot::kDegToRad, 0.0, 0.0}, Eigen::Vector3d::Zero(),
                            Eigen::Vector3d(5.0 * rot::kDegToRad, 0.0, 0.0), 200.0, 2.0 * rot::kPi / 10.0);
  Mechanisation r = start_at(traj.truth());
  for (int k = 0; k < 200 * 60; ++k) step(r, traj.next());
  EXPECT_LT(attitude_error_rad(r, traj.truth()), 1e-5);
  EXPECT_LT(r.x.vel_ned_mps.norm(), 2e-3);
}

TEST(Strapdown, FiveHertzRatesMatchTruth) {
  // A 5 Hz IMU reporting rates (UM220 GYOACC): the trapezoidal integration in ImuInput must keep
  // a static solution still even at this rate.
  test::LineTrajectory traj({45.0 * rot::kDegToRad, 0.0, 0.0}, Eigen::Vector3d::Zero(),
                            Eigen::Vector3d(1.0, 2.0, 100.0) * rot::kDegToRad, 5.0);
  Mechanisation r = start_at(traj.truth());
  ImuInput input;
  ImuSample first = traj.next();
  first.quantity = ImuQuantity::kRates;
  first.gyro /= first.dt_s;
  first.accel /= first.dt_s;
  ASSERT_FALSE(input.convert(first).has_value());  // nothing to integrate yet
  r = start_at(traj.truth());
  for (int k = 0; k < 5 * 120; ++k) {
    ImuSample s = traj.next();
    s.quantity = ImuQuantity::kRates;
    s.gyro /= s.dt_s;
    s.accel /= s.dt_s;
    const auto inc = input.convert(s);
    ASSERT_TRUE(inc.has_value());
    EXPECT_NEAR(inc->dt_s, 0.2, 1e-12);
    strapdown_step(r.x, r.memory, compensate(*inc, r.x), LocalEarth::at(r.x.lat_rad, r.x.height_m));
  }
  EXPECT_LT(r.x.vel_ned_mps.norm(), 1e-3);
  EXPECT_LT(attitude_error_rad(r, traj.truth()), 1e-6);
}

TEST(Strapdown, SensorFrameMountingIsApplied) {
  // A sensor mounted rolled 180 deg (upside down) reports x, -y, -z of the vehicle vectors.
  ImuInput input;
  input.set_mounting(rot::dcm_from_rpy(Eigen::Vector3d(rot::kPi, 0.0, 0.0)));
  ImuSample s;
  s.header.time_ns = 1000;
  s.quantity = ImuQuantity::kIncrements;
  s.frame = SensorFrame::kSensor;
  s.dt_s = 0.01;
  s.gyro = Eigen::Vector3d(0.1, 0.2, 0.3);
  s.accel = Eigen::Vector3d(1.0, 2.0, 3.0);
  const auto inc = input.convert(s);
  ASSERT_TRUE(inc.has_value());
  EXPECT_TRUE(inc->dtheta_rad.isApprox(Eigen::Vector3d(0.1, -0.2, -0.3), 1e-12));
  EXPECT_TRUE(inc->dvel_mps.isApprox(Eigen::Vector3d(1.0, -2.0, -3.0), 1e-12));
}

}  // namespace
}  // namespace navfuse::filter

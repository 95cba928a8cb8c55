// Truth trajectory: closed-form static and turn cases, and self-consistency through an
// independent high-rate strapdown integration of the true specific force and angular rate.
#include "apps/sim/trajectory.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geodesy/gravity.hpp"
#include "core/geodesy/wgs84.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

constexpr double kDeg = rot::kDegToRad;
constexpr double kOmega = geo::wgs84::kEarthRate_radps;
constexpr std::int64_t kStart = 1'400'000'000LL * 1'000'000'000LL;

TrajectorySpec at_start(double lat_deg, double yaw_deg) {
  TrajectorySpec t;
  t.start = {lat_deg * kDeg, 10.0 * kDeg, 0.0};
  t.initial_yaw_rad = yaw_deg * kDeg;
  return t;
}

TEST(Trajectory, StaticSpecificForceIsMinusGravityAndGyroSeesEarthRate) {
  // Level vehicle at rest on the ellipsoid, heading psi: f_b = -g_b with |g| from Somigliana's
  // closed form, and omega_ib_b = C_bn [W cos L, 0, -W sin L] = [W cosL cos psi,
  // -W cosL sin psi, -W sin L] (yaw-only C_bn by hand).
  const double lat = 45.0, yaw = 30.0;
  TrajectorySpec spec = at_start(lat, yaw);
  spec.segments = {MotionSegment::stationary(10.0)};
  const Trajectory traj(spec, kStart);
  TruthSample s = traj.initial();
  for (int i = 0; i < 100; ++i) s = traj.propagate(s, 50'000'000);
  EXPECT_TRUE(s.stationary);
  EXPECT_EQ(s.vel_ned_mps, Eigen::Vector3d::Zero());

  const double L = lat * kDeg, psi = yaw * kDeg;
  const double a = geo::wgs84::kSemiMajorAxis_m, b = geo::wgs84::kSemiMinorAxis_m;
  const double ge = geo::wgs84::kGravityEquator_mps2, gp = geo::wgs84::kGravityPole_mps2;
  const double k = (b * gp - a * ge) / (a * ge);
  const double e2 = geo::wgs84::kEccentricitySq;
  const double gamma = ge * (1 + k * std::sin(L) * std::sin(L)) / std::sqrt(1 - e2 * std::sin(L) * std::sin(L));
  EXPECT_NEAR(s.f_ib_b_mps2.z(), -gamma, 1e-6);
  EXPECT_NEAR(s.f_ib_b_mps2.x(), 0.0, 1e-6);  // no deflection of the normal on the ellipsoid
  EXPECT_NEAR(s.f_ib_b_mps2.y(), 0.0, 1e-6);
  EXPECT_NEAR(s.llh.lat_rad, L, 1e-15);
  EXPECT_NEAR(s.llh.height_m, 0.0, 1e-12);

  const Eigen::Vector3d w(kOmega * std::cos(L) * std::cos(psi), -kOmega * std::cos(L) * std::sin(psi),
                          -kOmega * std::sin(L));
  EXPECT_NEAR((s.omega_ib_b_rps - w).norm(), 0.0, 1e-15);
}

TEST(Trajectory, TurnFollowsTheSmoothStepInClosedForm) {
  // A 90 deg turn over 10 s at a constant 10 m/s: yaw(t) = psi0 + dpsi (tau - sin(2 pi tau)/2pi),
  // yaw rate dpsi/T (1 - cos 2 pi tau): at mid-turn twice the mean rate; centripetal f_y = u r.
  TrajectorySpec spec = at_start(30.0, 0.0);
  spec.segments = {MotionSegment::accelerate(10.0, 10.0), MotionSegment::turn(90.0 * kDeg, 10.0),
                   MotionSegment::cruise(5.0)};
  const Trajectory traj(spec, kStart);
  ASSERT_DOUBLE_EQ(traj.duration_s(), 25.0);

  TruthSample s = traj.initial();
  const std::int64_t dt = 5'000'000;
  for (int i = 0; i < 3000; ++i) s = traj.propagate(s, dt);  // 15 s: mid-turn
  EXPECT_NEAR(s.rpy_rad.z(), 45.0 * kDeg, 1e-12);
  EXPECT_NEAR(s.speed_mps, 10.0, 1e-12);
  const double r = 2.0 * 90.0 * kDeg / 10.0;  // peak yaw rate
  // Earth and transport rates add at most ~1e-4 rad/s to the body rate.
  EXPECT_NEAR(s.omega_ib_b_rps.z(), r, 1.5e-4);
  EXPECT_NEAR(s.f_ib_b_mps2.y(), 10.0 * r, 2e-3);  // Coriolis is ~1e-3 m/s^2 at 10 m/s
  EXPECT_NEAR(s.f_ib_b_mps2.x(), 0.0, 2e-3);

  for (int i = 0; i < 1000; ++i) s = traj.propagate(s, dt);  // 20 s: end of turn
  EXPECT_NEAR(s.rpy_rad.z(), 90.0 * kDeg, 1e-12);
  EXPECT_NEAR(s.omega_ib_b_rps.z(), 0.0, 1.5e-4);
  // Velocity points east, along the new heading.
  EXPECT_NEAR(s.vel_ned_mps.x(), 0.0, 1e-12);
  EXPECT_NEAR(s.vel_ned_mps.y(), 10.0, 1e-12);
}

TEST(Trajectory, AccelerateReachesTargetWithContinuousAcceleration) {
  // Speed 0 -> 20 m/s over 10 s: distance covered = mean speed * T = 100 m (the smooth step is
  // symmetric), peak acceleration 2 * 20 / 10 = 4 m/s^2 at mid-segment.
  TrajectorySpec spec = at_start(0.0, 0.0);  // northwards on the equator
  spec.segments = {MotionSegment::accelerate(20.0, 10.0)};
  const Trajectory traj(spec, kStart);
  const Kinematics mid = traj.kinematics(5.0);
  EXPECT_NEAR(mid.speed_rate_mps2, 4.0, 1e-12);
  EXPECT_NEAR(traj.kinematics(0.0).speed_rate_mps2, 0.0, 1e-12);
  EXPECT_NEAR(traj.kinematics(10.0).speed_rate_mps2, 0.0, 1e-12);
  TruthSample s = traj.initial();
  for (int i = 0; i < 2000; ++i) s = traj.propagate(s, 5'000'000);
  const geo::Radii radii = geo::radii_of_curvature(0.0);
  // Arc length along the meridian near the equator: R_N * dlat.
  EXPECT_NEAR((s.llh.lat_rad - spec.start.lat_rad) * radii.meridian_m, 100.0, 1e-6);
}

TEST(Trajectory, RejectsInconsistentSegments) {
  TrajectorySpec spec = at_start(0.0, 0.0);
  spec.segments = {MotionSegment::accelerate(5.0, 5.0), MotionSegment::stationary(5.0)};
  EXPECT_THROW(Trajectory(spec, kStart), std::invalid_argument);
  spec.segments = {MotionSegment::cruise(0.0)};
  EXPECT_THROW(Trajectory(spec, kStart), std::invalid_argument);
}

// ---- independent strapdown (NED mechanisation, Groves §5.4), classical RK4 -------------------
struct NavState {
  Eigen::Quaterniond q;
  Eigen::Vector3d v;
  double lat, lon, h;
};

struct NavRate {
  Eigen::Vector4d dq;  // (w, x, y, z)
  Eigen::Vector3d dv;
  Eigen::Vector3d dpos;
};

// Radii and rates written out here, not taken from core, so the check is independent.
NavRate nav_rate(const NavState& x, const Eigen::Vector3d& w_ib, const Eigen::Vector3d& f) {
  const double a = geo::wgs84::kSemiMajorAxis_m, e2 = geo::wgs84::kEccentricitySq;
  const double sl = std::sin(x.lat), cl = std::cos(x.lat);
  const double den = 1.0 - e2 * sl * sl;
  const double rn = a * (1 - e2) / std::pow(den, 1.5), re = a / std::sqrt(den);
  const Eigen::Vector3d w_ie(kOmega * cl, 0, -kOmega * sl);
  const Eigen::Vector3d w_en(x.v.y() / (re + x.h), -x.v.x() / (rn + x.h),
                             -x.v.y() * sl / cl / (re + x.h));
  const Eigen::Matrix3d c_nb = x.q.toRotationMatrix();
  const Eigen::Vector3d w_nb = w_ib - c_nb.transpose() * (w_ie + w_en);
  const Eigen::Quaterniond dq = x.q * Eigen::Quaterniond(0, w_nb.x(), w_nb.y(), w_nb.z());
  NavRate r;
  r.dq = 0.5 * Eigen::Vector4d(dq.w(), dq.x(), dq.y(), dq.z());
  r.dv = c_nb * f + geo::normal_gravity_ned(x.lat, x.h) - (w_en + 2 * w_ie).cross(x.v);
  r.dpos = {x.v.x() / (rn + x.h), x.v.y() / ((re + x.h) * cl), -x.v.z()};
  return r;
}

NavState add(const NavState& x, const NavRate& r, double h) {
  NavState y = x;
  y.q = Eigen::Quaterniond(x.q.w() + h * r.dq[0], x.q.x() + h * r.dq[1], x.q.y() + h * r.dq[2],
                           x.q.z() + h * r.dq[3]);
  y.v = x.v + h * r.dv;
  y.lat += h * r.dpos.x();
  y.lon += h * r.dpos.y();
  y.h += h * r.dpos.z();
  return y;
}

// 60 s with acceleration, turns, a climb and roll (camber) changing together, its non-slip point
// at `nonslip_point_m`; the integrator sees only omega_ib_b and f_ib_b (at 1 ms nodes, RK4 with
// 2 ms steps) and must end on the truth.
void expect_strapdown_reproduces_truth(const Eigen::Vector3d& nonslip_point_m) {
  TrajectorySpec spec = at_start(52.0, -20.0);
  spec.start.height_m = 120.0;
  spec.nonslip_point_m = nonslip_point_m;
  MotionSegment combined;
  combined.kind = MotionKind::kCombined;
  combined.duration_s = 12.0;
  combined.heading_change_rad = -70.0 * kDeg;
  combined.pitch_rad = -3.0 * kDeg;
  combined.roll_rad = -2.0 * kDeg;
  combined.speed_mps = 12.0;
  spec.segments = {MotionSegment::stationary(3.0), MotionSegment::accelerate(15.0, 8.0),
                   MotionSegment::turn(120.0 * kDeg, 10.0), MotionSegment::climb(5.0 * kDeg, 6.0),
                   combined, MotionSegment::climb(0.0, 6.0), MotionSegment::cruise(15.0)};
  const Trajectory traj(spec, kStart);
  ASSERT_DOUBLE_EQ(traj.duration_s(), 60.0);

  TruthSample t0 = traj.initial();
  NavState x{t0.q_nb, t0.vel_ned_mps, t0.llh.lat_rad, t0.llh.lon_rad, t0.llh.height_m};
  const std::int64_t half_ns = 1'000'000;
  const double h = 2e-3;
  for (int step = 0; step < 30000; ++step) {
    const TruthSample t1 = traj.propagate(t0, half_ns);
    const TruthSample t2 = traj.propagate(t1, half_ns);
    const NavRate k1 = nav_rate(x, t0.omega_ib_b_rps, t0.f_ib_b_mps2);
    const NavRate k2 = nav_rate(add(x, k1, h / 2), t1.omega_ib_b_rps, t1.f_ib_b_mps2);
    const NavRate k3 = nav_rate(add(x, k2, h / 2), t1.omega_ib_b_rps, t1.f_ib_b_mps2);
    const NavRate k4 = nav_rate(add(x, k3, h), t2.omega_ib_b_rps, t2.f_ib_b_mps2);
    NavRate sum;
    sum.dq = (k1.dq + 2 * k2.dq + 2 * k3.dq + k4.dq) / 6;
    sum.dv = (k1.dv + 2 * k2.dv + 2 * k3.dv + k4.dv) / 6;
    sum.dpos = (k1.dpos + 2 * k2.dpos + 2 * k3.dpos + k4.dpos) / 6;
    x = add(x, sum, h);
    x.q.normalize();
    t0 = t2;
  }
  const Eigen::Vector3d dpos = geo::ned_offset_m(t0.llh, {x.lat, x.lon, x.h});
  EXPECT_LT(dpos.norm(), 0.01) << dpos.transpose();
  EXPECT_LT((x.v - t0.vel_ned_mps).norm(), 1e-4);
  EXPECT_LT(rot::rotvec_from_quat(t0.q_nb.conjugate() * x.q).norm(), 1e-6);
  // And the truth really moved: ~700 m, with a climb.
  EXPECT_GT(geo::ned_offset_m(spec.start, t0.llh).head<2>().norm(), 500.0);
}

TEST(Trajectory, StrapdownOfTrueRatesReproducesTruth) { expect_strapdown_reproduces_truth(Eigen::Vector3d::Zero()); }

TEST(Trajectory, StrapdownOfTrueRatesReproducesTruthWithTheNonSlipPointAtARearAxle) {
  // The lever-arm terms of the velocity and its derivative (omega x (omega x l), omega_dot x l)
  // enter the specific force; a wrong sign or a missing term leaves the integrator metres off.
  expect_strapdown_reproduces_truth({-1.2, 0.1, 0.3});
}

TEST(Trajectory, RearAxleCarTurnsWithItsNoseSwingingOut) {
  // Mid-turn (90 deg over 10 s at 10 m/s) the yaw rate is r = 2 * 90 deg / 10 s; an IMU 1.2 m
  // ahead of the non-slip rear axle moves at v_b = u x_b - (omega x l) = (u, 1.2 r, 0) by hand
  // ((0, 0, r) x (-1.2, 0, 0) = (0, -1.2 r, 0)), earth and transport rates aside (~1e-4 rad/s).
  TrajectorySpec spec = at_start(30.0, 0.0);
  spec.nonslip_point_m = {-1.2, 0.0, 0.0};
  spec.segments = {MotionSegment::accelerate(10.0, 10.0), MotionSegment::turn(90.0 * kDeg, 10.0),
                   MotionSegment::cruise(5.0)};
  const Trajectory traj(spec, kStart);
  TruthSample s = traj.initial();
  for (int i = 0; i < 3000; ++i) s = traj.propagate(s, 5'000'000);  // 15 s
  const double r = 2.0 * 90.0 * kDeg / 10.0;
  const Eigen::Vector3d v_b = s.q_nb.conjugate() * s.vel_ned_mps;
  EXPECT_NEAR(v_b.x(), 10.0, 1e-12);
  EXPECT_NEAR(v_b.y(), 1.2 * r, 1e-12);
  EXPECT_NEAR(v_b.z(), 0.0, 1e-12);
  EXPECT_NEAR(s.speed_mps, 10.0, 1e-12);  // the axle's speed
  // The rigid-body velocity of the axle (omega_eb from the truth's own rates, as the wheel model
  // computes it) has no lateral or vertical part but the transport-rate slip the header bounds.
  const Eigen::Vector3d w_eb = s.omega_ib_b_rps - s.q_nb.conjugate() * geo::earth_rate_ned(s.llh.lat_rad);
  const Eigen::Vector3d v_axle = v_b + w_eb.cross(spec.nonslip_point_m);
  EXPECT_NEAR(v_axle.x(), 10.0, 1e-5);
  EXPECT_NEAR(v_axle.y(), 0.0, 1e-5);
  EXPECT_NEAR(v_axle.z(), 0.0, 1e-5);
}

TEST(Trajectory, AccelerationIsTheTimeDerivativeOfVelocityWithALeverArm) {
  // Central differences of the velocity (O(h^2), h = 1 ms) against the analytic derivative during
  // a combined turn, climb and roll: checks omega_nb_b's derivative term by term.
  TrajectorySpec spec = at_start(10.0, 40.0);
  spec.nonslip_point_m = {-1.5, 0.2, 0.4};
  MotionSegment combined;
  combined.kind = MotionKind::kCombined;
  combined.duration_s = 7.0;
  combined.heading_change_rad = 100.0 * kDeg;
  combined.pitch_rad = 6.0 * kDeg;
  combined.roll_rad = -5.0 * kDeg;
  combined.speed_mps = 8.0;
  spec.segments = {MotionSegment::accelerate(12.0, 5.0), combined};
  const Trajectory traj(spec, kStart);
  const double h = 1e-3;
  for (double t = 5.3; t < 12.0; t += 0.61) {
    const Eigen::Vector3d numeric =
        (traj.velocity_ned(traj.kinematics(t + h)) - traj.velocity_ned(traj.kinematics(t - h))) / (2.0 * h);
    EXPECT_LT((traj.acceleration_ned(traj.kinematics(t)) - numeric).norm(), 1e-5) << t;
  }
}

}  // namespace
}  // namespace navfuse::sim

// GNSS model: noise against the reported covariance, lever arm geometry, glitches and jumps,
// dual-antenna heading.
#include "apps/sim/gnss_model.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

constexpr double kDeg = rot::kDegToRad;
constexpr std::int64_t kStart = 1'400'000'000LL * 1'000'000'000LL;

// A vehicle standing at a fixed point with some attitude (truth rates are not needed here).
TruthSample standing(double yaw_deg, double pitch_deg, double roll_deg) {
  TruthSample t;
  t.time_ns = kStart;
  t.llh = {47.0 * kDeg, 8.0 * kDeg, 400.0};
  t.rpy_rad = {roll_deg * kDeg, pitch_deg * kDeg, yaw_deg * kDeg};
  t.q_nb = rot::quat_from_rpy(t.rpy_rad);
  t.omega_ib_b_rps = t.q_nb.conjugate() * geo::earth_rate_ned(t.llh.lat_rad);
  return t;
}

struct Errors {
  std::vector<Eigen::Vector3d> pos, vel;
  GnssPosition last_pos;
  GnssVelocity last_vel;
  int glitched = 0;
};

Errors run(const GnssSpec& spec, int epochs, std::uint64_t seed = 3) {
  GnssModel model(spec, seed);
  TruthSample t = standing(0.0, 0.0, 0.0);
  Errors e;
  GnssHeading h;
  for (int i = 0; i < epochs; ++i) {
    t.time_ns = kStart + i * model.period_ns();
    const auto epoch = model.make_epoch(t, i / spec.rate_hz, e.last_pos, e.last_vel, h);
    if (!epoch.has_position) continue;
    e.glitched += epoch.glitched;
    e.pos.push_back(geo::ned_offset_m(t.llh, {e.last_pos.lat_rad, e.last_pos.lon_rad, e.last_pos.height_m}));
    e.vel.push_back(e.last_vel.vel_ned_mps - t.vel_ned_mps);
  }
  return e;
}

double rms(const std::vector<Eigen::Vector3d>& v, int axis) {
  double ss = 0.0;
  for (const auto& x : v) ss += x[axis] * x[axis];
  return std::sqrt(ss / static_cast<double>(v.size()));
}

TEST(GnssModel, PositionAndVelocityNoiseMatchTheReportedCovariance) {
  // 40000 white epochs: RMS within ~0.4 % (1 sigma) of the reported sigma, per axis.
  const GnssSpec spec = gnss_standalone(5.0);
  const Errors e = run(spec, 40000);
  ASSERT_EQ(e.pos.size(), 40000u);
  EXPECT_DOUBLE_EQ(e.last_pos.cov_ned_m2(0, 0), 1.5 * 1.5);
  EXPECT_DOUBLE_EQ(e.last_pos.cov_ned_m2(2, 2), 3.0 * 3.0);
  EXPECT_EQ(e.last_pos.fix, GnssFixType::kFix3D);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(rms(e.pos, axis) / std::sqrt(e.last_pos.cov_ned_m2(axis, axis)), 1.0, 0.02);
    EXPECT_NEAR(rms(e.vel, axis) / std::sqrt(e.last_vel.cov_ned_m2ps2(axis, axis)), 1.0, 0.02);
  }
  // RTK: 2 cm / 3 cm.
  const Errors rtk = run(gnss_rtk_fixed(10.0), 20000);
  EXPECT_EQ(rtk.last_pos.fix, GnssFixType::kRtkFixed);
  EXPECT_NEAR(rms(rtk.pos, 0), 0.02, 0.02 * 0.03);
  EXPECT_NEAR(rms(rtk.pos, 2), 0.03, 0.03 * 0.03);
}

TEST(GnssModel, CorrelatedComponentKeepsTheTotalVarianceAndIsCorrelated) {
  // Half the variance Gauss-Markov with tau = 2 s at 5 Hz: the total RMS still equals the
  // reported sigma (40000 epochs = 4000 tau: within ~3 %), and successive errors correlate with
  // coefficient c * e^(-dt/tau) = 0.5 * e^-0.1 = 0.452.
  GnssSpec spec = gnss_standalone(5.0);
  spec.noise.correlated_fraction = 0.5;
  spec.noise.correlation_time_s = 2.0;
  const Errors e = run(spec, 40000);
  EXPECT_NEAR(rms(e.pos, 0) / 1.5, 1.0, 0.06);
  EXPECT_NEAR(rms(e.pos, 2) / 3.0, 1.0, 0.06);
  double c = 0.0, v = 0.0;
  for (std::size_t i = 1; i < e.pos.size(); ++i) {
    c += e.pos[i].x() * e.pos[i - 1].x();
    v += e.pos[i].x() * e.pos[i].x();
  }
  EXPECT_NEAR(c / v, 0.5 * std::exp(-0.1), 0.04);
}

TEST(GnssModel, AntennaPositionIsTruthPlusRotatedLeverArm) {
  // Noise-free receiver: ECEF(antenna) - ECEF(reference) = C_en C_nb l.
  GnssSpec spec = gnss_standalone(5.0);
  spec.noise.horizontal_std_m = spec.noise.vertical_std_m = 0.0;
  spec.noise.horizontal_velocity_std_mps = spec.noise.vertical_velocity_std_mps = 0.0;
  spec.lever_arm_m = {0.8, -0.4, -1.3};
  GnssModel model(spec, 1);
  const TruthSample t = standing(123.0, 4.0, -3.0);
  GnssPosition p;
  GnssVelocity v;
  GnssHeading h;
  ASSERT_TRUE(model.make_epoch(t, 0.0, p, v, h).has_position);
  const Eigen::Vector3d d = geo::ecef_from_llh({p.lat_rad, p.lon_rad, p.height_m}) - geo::ecef_from_llh(t.llh);
  const Eigen::Vector3d expected =
      geo::rot_ecef_from_ned(t.llh.lat_rad, t.llh.lon_rad) * rot::dcm_from_rpy(t.rpy_rad) * spec.lever_arm_m;
  EXPECT_LT((d - expected).norm(), 1e-6);
  EXPECT_LT(v.vel_ned_mps.norm(), 1e-12);  // at rest the antenna does not move either
}

TEST(GnssModel, AntennaVelocityIncludesTheLeverArmRotation) {
  // Yawing at r = 0.5 rad/s while driving north at 10 m/s (level, heading 0): an antenna at
  // l = (0.8, -0.4, 0) moves at v + r z x l = (10 + 0.2, 0.4, 0) (by hand: z x l = (0.4, 0.8, 0)).
  TruthSample t = standing(0.0, 0.0, 0.0);
  t.vel_ned_mps = {10.0, 0.0, 0.0};
  t.omega_ib_b_rps += Eigen::Vector3d(0.0, 0.0, 0.5);
  const Eigen::Vector3d v = lever_arm_velocity_ned(t, {0.8, -0.4, 0.0});
  EXPECT_NEAR(v.x(), 10.2, 1e-12);
  EXPECT_NEAR(v.y(), 0.4, 1e-12);
  EXPECT_NEAR(v.z(), 0.0, 1e-12);
}

TEST(GnssModel, GlitchesHitTheGivenFractionAndJumpsArePermanent) {
  GnssSpec spec = gnss_rtk_fixed(10.0);
  spec.glitch_fraction = 0.02;
  spec.glitch_offset_m = 50.0;
  spec.jumps = {{1000.0, Eigen::Vector3d(30.0, 0.0, 0.0)}};
  const Errors e = run(spec, 20000);  // 2000 s
  // Binomial: 400 expected, sigma 20.
  EXPECT_GT(e.glitched, 340);
  EXPECT_LT(e.glitched, 460);
  int big = 0;
  for (std::size_t i = 0; i < e.pos.size(); ++i) {
    Eigen::Vector3d d = e.pos[i];
    if (i >= 10000) d.x() -= 30.0;  // after the jump at 1000 s
    const double horizontal = d.head<2>().norm();
    if (horizontal > 1.0) {
      ++big;
      EXPECT_NEAR(horizontal, 50.0, 0.2);
    }
  }
  EXPECT_EQ(big, e.glitched);
  // The jump is in every non-glitched fix from 1000 s on, and in none before (RTK noise 2 cm).
  for (std::size_t i = 0; i < e.pos.size(); ++i) {
    const double north = e.pos[i].x();
    if (std::abs(north) < 0.2 || std::abs(north - 30.0) < 0.2) {
      EXPECT_NEAR(north, i >= 10000 ? 30.0 : 0.0, 0.2) << i;
    }
  }
}

TEST(GnssModel, OutagesProduceNothing) {
  GnssSpec spec = gnss_standalone(5.0);
  spec.outages = {{10.0, 20.0}};
  GnssModel model(spec, 1);
  EXPECT_TRUE(model.available(9.99));
  EXPECT_FALSE(model.available(10.0));
  EXPECT_FALSE(model.available(19.99));
  EXPECT_TRUE(model.available(20.0));
  GnssPosition p;
  GnssVelocity v;
  GnssHeading h;
  const auto epoch = model.make_epoch(standing(0, 0, 0), 15.0, p, v, h);
  EXPECT_FALSE(epoch.has_position || epoch.has_velocity || epoch.has_heading);
}

TEST(GnssModel, DualAntennaHeadingIsTheBaselineAzimuth) {
  // Secondary 1.5 m behind the primary: the baseline points along -x, so its azimuth is the
  // vehicle yaw + 180 deg and its elevation minus the pitch.
  GnssSpec spec = gnss_standalone(5.0);
  spec.heading = true;
  spec.heading_std_rad = 0.0;
  spec.heading_pitch_std_rad = 0.0;
  spec.lever_arm_m = {0.8, -0.4, -1.3};
  spec.secondary_lever_arm_m = {-0.7, -0.4, -1.3};
  GnssModel model(spec, 1);
  GnssPosition p;
  GnssVelocity v;
  GnssHeading h;
  ASSERT_TRUE(model.make_epoch(standing(30.0, 5.0, 0.0), 0.0, p, v, h).has_heading);
  EXPECT_NEAR(h.heading_rad, rot::wrap_pi((30.0 + 180.0) * kDeg), 1e-12);
  EXPECT_NEAR(h.pitch_rad, -5.0 * kDeg, 1e-12);
  EXPECT_NEAR(h.baseline_m, 1.5, 1e-12);
}

}  // namespace
}  // namespace navfuse::sim

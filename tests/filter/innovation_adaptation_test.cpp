// Innovation-based adaptation on closed-form streams: an overconfident filter notices within a
// second and takes a persistent GNSS change instead of rejecting it for seconds; a lone outlier
// is still rejected and changes nothing; the window's median ignores single samples.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/rotation/rotation.hpp"
#include "filter/control/innovation_adaptation.hpp"
#include "filter/engine.hpp"
#include "tests/filter/line_trajectory.hpp"

namespace navfuse::filter {
namespace {

constexpr double kLat = 40.0 * rot::kDegToRad;
const Eigen::Vector3d kRpy = Eigen::Vector3d(1.0, -2.0, 60.0) * rot::kDegToRad;

TEST(InnovationWindow, MedianOfRecentSamplesOnly) {
  InnovationWindow w;
  const std::int64_t s = 1'000'000'000;
  auto push = [&w](std::int64_t t, double v) { w.push({t, v, 10.0 * v, {v, 0.0, 0.0}}); };
  EXPECT_FALSE(w.recent_medians(0, 1.0, 1));
  push(0, 100.0);  // old
  push(2 * s, 1.0);
  push(2 * s + s / 4, 500.0);  // a lone outlier
  push(2 * s + s / 2, 2.0);
  const auto m = w.recent_medians(2 * s + s / 2, 1.0, 3);  // {1, 500, 2}: not moved by 500
  ASSERT_TRUE(m);
  EXPECT_DOUBLE_EQ(m->nis_per_dim, 2.0);
  EXPECT_DOUBLE_EQ(m->lambda, 20.0);
  EXPECT_FALSE(w.recent_medians(2 * s + s / 2, 1.0, 4));  // only 3 are recent
  for (int i = 0; i < 40; ++i) push(3 * s + i, 7.0);       // wraps the fixed capacity
  EXPECT_EQ(w.count, InnovationWindow::kCapacity);
  EXPECT_DOUBLE_EQ(w.recent_medians(3 * s + 40, 1.0, 3)->nis_per_dim, 7.0);
}

TEST(InnovationWindow, LargeResidualsMustAgree) {
  const std::int64_t s = 1'000'000'000;
  InnovationWindow drift, glitches;
  for (int i = 0; i < 4; ++i) {
    // One offset growing north (a filter drifting off a healthy stream) ...
    drift.push({i * s / 4, 9.0, 9.0, {0.3 + 0.05 * i, 0.02 * (i % 2), 0.0}});
    // ... against 50 m glitches in four directions.
    const double a = 1.5707963267948966 * i;
    glitches.push({i * s / 4, 900.0, 900.0, {50.0 * std::cos(a), 50.0 * std::sin(a), 0.0}});
  }
  EXPECT_TRUE(drift.recent_medians(s, 1.0, 3, 3.0)->residuals_agree);
  EXPECT_FALSE(glitches.recent_medians(s, 1.0, 3, 3.0)->residuals_agree);
}

// Standing still with a known heading, RTK-like fixes (2 cm) at 5 Hz for 30 s; from 20 s on the
// fixes are `step_m` north of the truth (a new base station, a datum change), and the fix at
// `outlier_s` (if > 0) is 10 m off once.
struct Outcome {
  std::uint64_t gated = 0;
  std::uint64_t inflations = 0;
  std::uint64_t recoveries = 0;
  double process_noise_scale = 0.0;  // at the end
  double final_north_m = 0.0;  // estimate minus truth
};

Outcome run(double step_m, double outlier_s, bool adaptation) {
  FilterOptions o;
  o.initial_heading_rad = kRpy.z();
  o.adaptation.enabled = adaptation;
  Engine e{o};
  test::LineTrajectory traj({kLat, 0.2, 100.0}, Eigen::Vector3d::Zero(), kRpy, 200.0);
  std::mt19937_64 rng(11);
  for (int k = 1; k <= 30 * 200; ++k) {
    e.process(traj.next());
    if (k % 40 != 0) continue;
    const double t = k / 200.0;
    GnssPosition fix = test::make_fix(traj.truth(), Eigen::Vector3d::Zero(), 0.02, &rng);
    fix.fix = GnssFixType::kRtkFixed;
    double north = t >= 20.0 ? step_m : 0.0;
    if (outlier_s > 0.0 && std::abs(t - outlier_s) < 1e-9) north += 10.0;
    const geo::Llh moved = geo::llh_offset({fix.lat_rad, fix.lon_rad, fix.height_m}, Eigen::Vector3d(north, 0, 0));
    fix.lat_rad = moved.lat_rad;
    e.process(Measurement{fix});
  }
  Outcome out;
  const FilterStats stats = e.stats();
  out.gated = stats.of(MeasurementKind::kGnssPosition).rejected_for(RejectReason::kChi2Gate);
  out.inflations = stats.covariance_inflations;
  out.recoveries = stats.gnss_recoveries;
  out.process_noise_scale = stats.process_noise_scale;
  out.final_north_m = geo::ned_offset_m(traj.truth().llh, {e.solution().lat_rad, e.solution().lon_rad,
                                                           e.solution().height_m}).x();
  return out;
}

TEST(InnovationAdaptation, PersistentChangeIsTakenWithinASecond) {
  const Outcome with = run(0.5, 0.0, true);
  // At 5 Hz the window holds 3 disagreeing fixes after 0.4 s: at most those are gated.
  EXPECT_LE(with.gated, 3u);
  EXPECT_GE(with.inflations, 1u);
  EXPECT_EQ(with.recoveries, 0u);
  EXPECT_NEAR(with.final_north_m, 0.5, 0.05);
  // Without adaptation the same stream is rejected for gnss_recovery_s (3 s) until a re-anchor.
  const Outcome without = run(0.5, 0.0, false);
  EXPECT_GE(without.gated, 10u);
  EXPECT_GE(without.recoveries, 1u);
}

TEST(InnovationAdaptation, LoneOutlierIsRejectedAndChangesNothing) {
  const Outcome r = run(0.0, 12.0, true);
  EXPECT_EQ(r.gated, 1u);
  EXPECT_EQ(r.inflations, 0u);
  EXPECT_NEAR(r.final_north_m, 0.0, 0.03);
}

TEST(InnovationAdaptation, ConsistentFilterKeepsTheDataSheetNoise) {
  const Outcome r = run(0.0, 0.0, true);
  EXPECT_EQ(r.inflations, 0u);
  EXPECT_EQ(r.gated, 0u);
  // The start (levelling, the first fixes) may raise it; consistent innovations bring it back.
  EXPECT_LT(r.process_noise_scale, 1.5);
}

}  // namespace
}  // namespace navfuse::filter

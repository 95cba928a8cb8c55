// Error metrics against hand-computed values on constructed pairs of solutions: known position
// offsets, velocity differences and rotations, including a heading pair straddling +-180 deg.
#include "apps/bench/error_metrics.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps::bench {
namespace {

constexpr double kDeg = rot::kDegToRad;
constexpr std::uint32_t kAll = NavSolution::kValidPosition | NavSolution::kValidVelocity |
                               NavSolution::kValidAttitude | NavSolution::kValidHeading;
constexpr std::uint32_t kAllStd =
    NavSolution::kValidPositionStd | NavSolution::kValidVelocityStd | NavSolution::kValidAttitudeStd;

TrackSample reference() {
  TrackSample s;
  s.mode = NavMode::kNavigation;
  s.valid = kAll;
  s.lat_rad = 45.0 * kDeg;
  s.lon_rad = 7.0 * kDeg;
  s.height_m = 300.0;
  s.vel_ned_mps = {10.0, 5.0, 0.0};
  s.rpy_rad = Eigen::Vector3d(2.0, -1.0, -179.0) * kDeg;
  return s;
}

// `ref` moved by a NED offset, with other velocity and attitude.
TrackSample offset(const TrackSample& ref, const Eigen::Vector3d& ned_m) {
  TrackSample s = ref;
  const geo::Llh p = geo::llh_offset({ref.lat_rad, ref.lon_rad, ref.height_m}, ned_m);
  s.lat_rad = p.lat_rad;
  s.lon_rad = p.lon_rad;
  s.height_m = ref.height_m - ned_m.z();  // exactly 'down' metres lower
  return s;
}

TEST(ErrorMetrics, KnownOffsetsAndRotationsGiveHandComputedErrors) {
  const TrackSample ref = reference();
  TrackSample est = offset(ref, {3.0, 4.0, -2.0});        // 3 m north, 4 m east, 2 m up
  est.vel_ned_mps = ref.vel_ned_mps + Eigen::Vector3d(1.0, 2.0, -2.0);
  est.rpy_rad = Eigen::Vector3d(3.0, -3.0, 179.0) * kDeg;  // roll +1, pitch -2, heading -2 across +-180
  const SolutionError e = solution_error(est, ref, /*reference_is_truth=*/true);
  ASSERT_TRUE(e.any());
  EXPECT_NEAR(e.position_ned_m.x(), 3.0, 1e-6);
  EXPECT_NEAR(e.position_ned_m.y(), 4.0, 1e-6);
  EXPECT_NEAR(e.position_ned_m.z(), -2.0, 1e-9);
  EXPECT_NEAR(*metric_value(e, Metric::kHorizontal), 5.0, 1e-6);
  EXPECT_NEAR(*metric_value(e, Metric::kVertical), 2.0, 1e-9);
  EXPECT_NEAR(*metric_value(e, Metric::kPosition3d), std::sqrt(29.0), 1e-6);
  EXPECT_NEAR(*metric_value(e, Metric::kVelocity), 3.0, 1e-12);
  EXPECT_NEAR(*metric_value(e, Metric::kRoll), 1.0, 1e-9);
  EXPECT_NEAR(*metric_value(e, Metric::kPitch), 2.0, 1e-9);
  // 179 - (-179) = 358 deg of raw difference is a 2 deg error, estimate counter-clockwise of the
  // reference: signed -2 deg.
  EXPECT_NEAR(*metric_value(e, Metric::kHeading), 2.0, 1e-9);
  EXPECT_NEAR(e.rpy_rad.z(), -2.0 * kDeg, 1e-12);
  EXPECT_NEAR(e.rpy_rad.y(), -2.0 * kDeg, 1e-12);
}

TEST(ErrorMetrics, QuantitiesOneSideLacksAreLeftOut) {
  const TrackSample ref = reference();
  TrackSample est = ref;
  est.valid = NavSolution::kValidAttitude;  // levelled, no heading, no position
  const SolutionError e = solution_error(est, ref, true);
  EXPECT_FALSE(metric_value(e, Metric::kHorizontal));
  EXPECT_FALSE(metric_value(e, Metric::kVelocity));
  EXPECT_FALSE(metric_value(e, Metric::kHeading));
  EXPECT_TRUE(metric_value(e, Metric::kRoll));
  est.valid = 0;
  EXPECT_FALSE(solution_error(est, ref, true).any());
}

TEST(ErrorMetrics, SigmaIsTheEstimatesAgainstTruthAndTheRootSumOfSquaresOtherwise) {
  TrackSample ref = reference();
  TrackSample est = offset(ref, {1.0, 0.0, 0.0});
  est.valid |= kAllStd;
  est.pos_std_ned_m = {3.0, 3.0, 6.0};
  est.att_std_rpy_rad = Eigen::Vector3d(0.1, 0.2, 0.3) * kDeg;
  const SolutionError vs_truth = solution_error(est, ref, true);
  EXPECT_DOUBLE_EQ(vs_truth.position_sigma_m.x(), 3.0);
  EXPECT_NEAR(vs_truth.rpy_sigma_rad.z(), 0.3 * kDeg, 1e-15);
  // The device reports no uncertainty: the combined sigma is unknown.
  EXPECT_TRUE(std::isnan(solution_error(est, ref, false).position_sigma_m.x()));
  ref.valid |= kAllStd;
  ref.pos_std_ned_m = {4.0, 4.0, 8.0};
  const SolutionError vs_device = solution_error(est, ref, false);
  EXPECT_DOUBLE_EQ(vs_device.position_sigma_m.x(), 5.0);  // 3-4-5
  EXPECT_DOUBLE_EQ(vs_device.position_sigma_m.z(), 10.0);
}

TEST(MetricSet, StatisticsAreRmsAndNearestRankPercentiles) {
  // Horizontal errors 1, 2, ..., 100 m (north only).
  MetricSet set;
  const TrackSample ref = reference();
  for (int k = 1; k <= 100; ++k) {
    TrackSample est = offset(ref, {static_cast<double>(k), 0.0, 0.0});
    SolutionError e = solution_error(est, ref, true);
    e.time_ns = k * 1'000'000'000LL;
    set.add(e);
  }
  const ErrorSummary h = set.summary(Metric::kHorizontal);
  EXPECT_EQ(h.samples, 100u);
  // sum k^2 for k = 1..100 = 100 * 101 * 201 / 6 = 338350.
  EXPECT_NEAR(h.rms, std::sqrt(338350.0 / 100.0), 1e-4);
  EXPECT_NEAR(h.p50, 50.0, 1e-4);
  EXPECT_NEAR(h.p95, 95.0, 1e-4);
  EXPECT_NEAR(h.p99, 99.0, 1e-4);
  EXPECT_NEAR(h.max, 100.0, 1e-4);
  EXPECT_DOUBLE_EQ(set.span_s(), 99.0);
  const auto j = set.metrics_json();
  EXPECT_EQ(j["samples"], 100);
  EXPECT_NEAR(j["horizontal_m"]["p95"].get<double>(), 95.0, 1e-4);
  EXPECT_DOUBLE_EQ(j["heading_deg"]["max"].get<double>(), 0.0);
}

TEST(MetricSet, ConsistencyCountsErrorsWithinOneTwoAndThreeSigma) {
  // Sigma 1 m north; errors 0.5, 1.0 (on the boundary: inside), 1.5, 2.5, 3.5 m.
  MetricSet set;
  for (double err : {0.5, 1.0, 1.5, 2.5, 3.5}) {
    SolutionError e;
    e.has[static_cast<std::size_t>(Quantity::kPosition)] = true;
    e.position_ned_m = {-err, 0.0, 0.0};
    e.position_sigma_m = {1.0, 2.0 * err, std::numeric_limits<double>::quiet_NaN()};
    set.add(e);
  }
  const ConsistencyCount& north = set.consistency(Axis::kNorth);
  EXPECT_EQ(north.samples, 5u);
  EXPECT_EQ(north.within[0], 2u);
  EXPECT_EQ(north.within[1], 3u);
  EXPECT_EQ(north.within[2], 4u);
  EXPECT_EQ(set.consistency(Axis::kEast).within[0], 5u);  // zero error, any sigma
  EXPECT_EQ(set.consistency(Axis::kDown).samples, 0u);    // no sigma: not counted
  const auto j = set.consistency_json();
  EXPECT_DOUBLE_EQ(j["position_north"]["within_1sigma"].get<double>(), 0.4);
  EXPECT_DOUBLE_EQ(j["position_north"]["within_3sigma"].get<double>(), 0.8);
  EXPECT_FALSE(j.contains("position_down"));
}

}  // namespace
}  // namespace navfuse::apps::bench

// A constructed pair of trajectories: navfuse at 100 Hz, the device at 10 Hz, offset by a known
// amount and turning through +-180 deg of heading, with a dropout in navfuse's solution. The
// comparison must give the offsets exactly, skip (not bridge) the dropout, and split by phase.
#include "apps/bench/pair_comparison.hpp"

#include <gtest/gtest.h>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps::bench {
namespace {

constexpr double kDeg = rot::kDegToRad;
constexpr std::int64_t kMs = 1'000'000;
const geo::Llh kStart{0.7, 0.2, 100.0};

// Driving north-east at 10 m/s while the heading turns at 10 deg/s, starting at 170 deg.
TrackSample truth_at(std::int64_t t_ns) {
  const double t = static_cast<double>(t_ns) * 1e-9;
  const geo::Llh p = geo::llh_offset(kStart, {7.0 * t, 7.0 * t, 0.0});
  TrackSample s;
  s.time_ns = t_ns;
  s.mode = NavMode::kNavigation;
  s.valid = NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
            NavSolution::kValidHeading;
  s.lat_rad = p.lat_rad;
  s.lon_rad = p.lon_rad;
  s.height_m = p.height_m;
  s.vel_ned_mps = {7.0, 7.0, 0.0};
  s.rpy_rad = {1.0 * kDeg, -0.5 * kDeg, rot::wrap_pi((170.0 + 10.0 * t) * kDeg)};
  return s;
}

TEST(PairComparison, ConstantOffsetsThroughTheHeadingWrapAndNoBridgingOfADropout) {
  SolutionTrack navfuse, device;
  for (std::int64_t t = 0; t <= 4000 * kMs; t += 10 * kMs) {
    if (t > 2000 * kMs && t < 2500 * kMs) continue;  // navfuse lost its solution for 0.5 s
    TrackSample s = truth_at(t);
    // navfuse: 0.6 m north, 0.8 m east, 0.5 m high, 0.2 m/s fast north, heading +0.3 deg.
    const TrackSample moved = s;
    const geo::Llh p = geo::llh_offset({s.lat_rad, s.lon_rad, s.height_m}, {0.6, 0.8, 0.0});
    s.lat_rad = p.lat_rad;
    s.lon_rad = p.lon_rad;
    s.height_m = moved.height_m + 0.5;
    s.vel_ned_mps.x() += 0.2;
    s.rpy_rad.z() = rot::wrap_pi(s.rpy_rad.z() + 0.3 * kDeg);
    navfuse.append(s);
  }
  for (std::int64_t t = 0; t <= 4000 * kMs; t += 100 * kMs) device.append(truth_at(t));

  const auto nf_view = navfuse.with(Quantity::kPosition, true);
  TrackInterpolator nf(nf_view, default_max_gap_ns(nf_view));
  PhaseTimeline phases;
  phases.add(0, {.gnss_outage = false, .stationary = false});
  phases.add(3000 * kMs, {.gnss_outage = true, .stationary = false});
  const PairSpec spec{.name = "navfuse_vs_device", .estimate = "navfuse", .reference = "device",
                      .reference_is_truth = false, .sampled_is_estimate = false};
  const PairComparison pair = compare_pair(spec, device.with_any(), interpolating_lookup(nf), phases);

  // 41 device epochs, 4 of them (2.1 .. 2.4 s) inside navfuse's dropout.
  EXPECT_EQ(pair.gaps, 4u);
  EXPECT_EQ(pair.outside, 0u);
  EXPECT_EQ(pair.samples(), 37u);
  EXPECT_DOUBLE_EQ(pair.overlap_s(), 4.0);
  const MetricSet& all = pair.metrics.all();
  // Interpolating navfuse's 100 Hz straight-line track is exact to well under a millimetre.
  EXPECT_NEAR(all.summary(Metric::kHorizontal).max, 1.0, 1e-3);
  EXPECT_NEAR(all.summary(Metric::kHorizontal).rms, 1.0, 1e-3);
  EXPECT_NEAR(all.summary(Metric::kVertical).p50, 0.5, 1e-6);
  EXPECT_NEAR(all.summary(Metric::kVelocity).max, 0.2, 1e-9);
  // The heading crosses +-180 deg at t = 1 s; the error stays 0.3 deg throughout.
  EXPECT_NEAR(all.summary(Metric::kHeading).max, 0.3, 1e-6);
  EXPECT_NEAR(all.summary(Metric::kHeading).p50, 0.3, 1e-6);
  EXPECT_NEAR(all.summary(Metric::kRoll).max, 0.0, 1e-9);
  // Phases: 0 .. 2.9 s available (26 aligned epochs: 30 minus 4 in the gap), 3.0 .. 4.0 s outage.
  EXPECT_EQ(pair.metrics.phase(Phase::kGnssAvailable).samples(), 26u);
  EXPECT_EQ(pair.metrics.phase(Phase::kGnssOutage).samples(), 11u);
  EXPECT_EQ(pair.metrics.phase(Phase::kMoving).samples(), 37u);
  const auto j = pair.to_json();
  EXPECT_EQ(j["unaligned"]["gap"], 4);
  EXPECT_TRUE(j.contains("heading_deg"));
  EXPECT_TRUE(j["by_mode"].contains("navigation"));
}

TEST(PhaseTimeline, StepLabelsIntervalsAndGnssOutagesFromFixTimes) {
  PhaseTimeline timeline;
  timeline.add(0, {.gnss_outage = false, .stationary = true});
  timeline.add(10, {.gnss_outage = true, .stationary = false});
  timeline.add(20, {.gnss_outage = true, .stationary = false});
  timeline.add(30, {.gnss_outage = false, .stationary = false});
  PhaseTimeline::Cursor cursor = timeline.cursor();
  EXPECT_TRUE(cursor.at(-5)->stationary);
  EXPECT_TRUE(cursor.at(15)->gnss_outage);
  EXPECT_FALSE(cursor.at(35)->gnss_outage);
  EXPECT_TRUE(cursor.at(10)->gnss_outage);  // back in time: read again from the start
  EXPECT_FALSE(cursor.at(9)->gnss_outage);
  ASSERT_EQ(timeline.outages().size(), 1u);
  EXPECT_EQ(timeline.outages()[0].start_ns, 10);
  EXPECT_EQ(timeline.outages()[0].end_ns, 30);
  ASSERT_EQ(timeline.stationary_periods().size(), 1u);
  EXPECT_EQ(timeline.stationary_periods()[0].end_ns, 10);

  // 5 Hz fixes with a 10 s hole: the age limit is max(1 s, 2.5 x 200 ms) = 1 s.
  // Added out of order (a late fix), as the fusion run may report them.
  ExternalSort<std::int64_t> fixes(8);
  for (std::int64_t t = 20'000 * kMs; t >= 0; t -= 200 * kMs) {
    if (t < 5000 * kMs || t > 15'000 * kMs) fixes.add(t);
  }
  GnssOutageDetector outage(fixes);
  EXPECT_EQ(outage.max_fix_age_ns(), 1000 * kMs);
  EXPECT_TRUE(outage.at(-1));
  EXPECT_FALSE(outage.at(5500 * kMs));
  EXPECT_TRUE(outage.at(6100 * kMs));
  EXPECT_FALSE(outage.at(15'300 * kMs));
  EXPECT_FALSE(outage.at(4000 * kMs));  // back in time

  // 0.5 Hz fixes: the age limit is 2.5 x the median interval, 5 s.
  ExternalSort<std::int64_t> slow;
  for (std::int64_t t = 0; t <= 60'000 * kMs; t += 2000 * kMs) slow.add(t);
  EXPECT_EQ(GnssOutageDetector(slow).max_fix_age_ns(), 5000 * kMs);
}

}  // namespace
}  // namespace navfuse::apps::bench

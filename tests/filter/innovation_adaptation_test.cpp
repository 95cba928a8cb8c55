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
#include "tests/filter/standing_fixes.hpp"

namespace navfuse::filter {
namespace {

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

// The standing stream of standing_fixes.hpp for 30 s: from 20 s on the fixes are `change_m`
// north of the truth, reached over `ramp_s` (0: in one step); the fix at `outlier_s` (if > 0) is
// 10 m off once.
test::StandingOutcome run(double change_m, double outlier_s, bool adaptation, double ramp_s = 0.0,
                          double jump_hold_s = FilterOptions{}.gnss_jump_hold_s) {
  FilterOptions o;
  o.adaptation.enabled = adaptation;
  o.gnss_jump_hold_s = jump_hold_s;
  return test::run_standing(o, 30.0, [&](double t) {
    double north = t < 20.0 ? 0.0 : ramp_s > 0.0 ? change_m * std::min(1.0, (t - 20.0) / ramp_s) : change_m;
    if (outlier_s > 0.0 && std::abs(t - outlier_s) < 1e-9) north += 10.0;
    return north;
  });
}

// An overconfident filter: what it holds still, the fixes show moving away (0.5 m in 2 s, steps
// of 5 cm between fixes, none a jump). It must notice within a second and follow.
TEST(InnovationAdaptation, PersistentChangeIsTakenWithinASecond) {
  const test::StandingOutcome with = run(0.5, 0.0, true, 2.0);
  // At 5 Hz the window holds 3 disagreeing fixes after 0.4 s: at most those are gated.
  EXPECT_LE(with.gated, 3u);
  EXPECT_EQ(with.jumps, 0u);
  EXPECT_GE(with.inflations, 1u);
  EXPECT_EQ(with.recoveries, 0u);
  EXPECT_NEAR(with.final_north_m, 0.5, 0.05);
  // Without adaptation the same stream is rejected for gnss_recovery_s (3 s) until a re-anchor.
  const test::StandingOutcome without = run(0.5, 0.0, false, 2.0);
  EXPECT_GE(without.gated, 10u);
  EXPECT_GE(without.recoveries, 1u);
  // A 0.5 m step in one epoch is taken as quickly when the step check is off (gnss.jump_hold_s
  // 0); with it, gnss_jump_check_test.cpp.
  const test::StandingOutcome step = run(0.5, 0.0, true, 0.0, 0.0);
  EXPECT_LE(step.gated, 3u);
  EXPECT_GE(step.inflations, 1u);
  EXPECT_NEAR(step.final_north_m, 0.5, 0.05);
}

TEST(InnovationAdaptation, LoneOutlierIsRejectedAndChangesNothing) {
  const test::StandingOutcome r = run(0.0, 12.0, true);
  EXPECT_EQ(r.gated + r.jumps, 1u);  // a 10 m step from the previous fix: rejected as gnss_jump
  EXPECT_EQ(r.inflations, 0u);
  EXPECT_NEAR(r.final_north_m, 0.0, 0.03);
}

TEST(InnovationAdaptation, ConsistentFilterKeepsTheDataSheetNoise) {
  const test::StandingOutcome r = run(0.0, 0.0, true);
  EXPECT_EQ(r.inflations, 0u);
  EXPECT_EQ(r.gated, 0u);
  EXPECT_EQ(r.jumps, 0u);
  // The start (levelling, the first fixes) may raise it; consistent innovations bring it back.
  EXPECT_LT(r.process_noise_scale, 1.5);
}

}  // namespace
}  // namespace navfuse::filter

// The GNSS step check (filter/control/gnss_jump_check.hpp) on the closed-form standing stream of
// standing_fixes.hpp: fixes that step away from the inertial track are held out while the step
// lasts, the filter keeps the truth, and neither adaptation takes the step for a drifting filter;
// a step that lasts beyond gnss.jump_hold_s is taken. A ramp (an overconfident filter drifting off
// the fixes) is not a step: innovation_adaptation_test.cpp asserts that no fix of it is held out.
#include <gtest/gtest.h>

#include <cmath>

#include "filter/engine.hpp"
#include "tests/filter/standing_fixes.hpp"

namespace navfuse::filter {
namespace {

constexpr double kFixesPerS = 5.0;

// A 3 s multipath event of 0.5 m from 20 s: its 15 fixes are rejected as displaced (none at the
// gate, no re-inflation), the filter stays on the truth within what the fixes' noise allows.
TEST(GnssJumpCheck, AMultipathEventIsHeldOutWhileItLasts) {
  const test::StandingOutcome r =
      test::run_standing(FilterOptions{}, 30.0, [](double t) { return t >= 20.0 && t < 23.0 ? 0.5 : 0.0; });
  EXPECT_EQ(r.jumps, static_cast<std::uint64_t>(3.0 * kFixesPerS));
  EXPECT_EQ(r.gated, 0u);
  EXPECT_EQ(r.inflations, 0u);
  EXPECT_EQ(r.recoveries, 0u);
  EXPECT_LT(r.max_north_m, 0.03);
  // The same event without the check: the adaptation follows the offset within a second.
  FilterOptions off;
  off.gnss_jump_hold_s = 0.0;
  const test::StandingOutcome followed =
      test::run_standing(off, 30.0, [](double t) { return t >= 20.0 && t < 23.0 ? 0.5 : 0.0; });
  EXPECT_EQ(followed.jumps, 0u);
  EXPECT_GE(followed.inflations, 1u);
  EXPECT_GT(followed.max_north_m, 0.3);
}

// A step that stays (a new reference station, a datum change) is held out for jump_hold_s, then
// the usual recovery takes it: by the end the filter is on the new level.
TEST(GnssJumpCheck, AStepThatStaysIsTakenAfterTheHold) {
  FilterOptions o;
  o.gnss_jump_hold_s = 4.0;
  const test::StandingOutcome r = test::run_standing(o, 30.0, [](double t) { return t >= 20.0 ? 0.5 : 0.0; });
  // 4 s of fixes held out (one more for the epoch at the hold's end), then followed.
  EXPECT_GE(r.jumps, static_cast<std::uint64_t>(4.0 * kFixesPerS));
  EXPECT_LE(r.jumps, static_cast<std::uint64_t>(4.0 * kFixesPerS) + 1);
  EXPECT_NEAR(r.final_north_m, 0.5, 0.05);
}

// Standing still with noise only: no fix is ever taken for a step (30 s, 150 fixes).
TEST(GnssJumpCheck, AQuietStreamHasNoSteps) {
  const test::StandingOutcome r = test::run_standing(FilterOptions{}, 30.0, [](double) { return 0.0; });
  EXPECT_EQ(r.jumps, 0u);
  EXPECT_EQ(r.gated, 0u);
}

}  // namespace
}  // namespace navfuse::filter

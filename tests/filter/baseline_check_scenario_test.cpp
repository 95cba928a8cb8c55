// Issue 17: a dual-antenna baseline configured 180 deg wrong (antennas swapped) is found against
// the course over ground within 10 s of motion, flagged in the status (kStatusHeadingOffset) with
// the GNSS headings rejected as "baseline_mismatch", and the heading is then the course's. The
// same drive with the right baseline is never flagged.
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/filter/scenario_harness.hpp"

namespace navfuse::filter {
namespace {

struct BaselineRun {
  double flagged_at_s = -1.0;
  double first_motion_s = -1.0;
  test::Rms heading_after;  // from 30 s after the flag (or after motion when never flagged)
  test::Rms horizontal_after;
  FilterStats stats;
};

BaselineRun run_dual_antenna(double baseline_error_rad) {
  const sim::Scenario s = sim::make_scenario("dual_antenna");
  BaselineRun r;
  const auto summary = test::run_scenario(
      s, test::options_for(s),
      [&](const test::Epoch& e) {
        const NavSolution& sol = e.engine->solution();
        if (r.flagged_at_s < 0.0 && (sol.status_flags & NavSolution::kStatusHeadingOffset) != 0) {
          r.flagged_at_s = e.t_s;
        }
        const double since = r.flagged_at_s >= 0.0 ? r.flagged_at_s : 60.0;
        if (e.t_s > since + 30.0) {
          r.heading_after.add(e.rpy_err_rad.z());
          r.horizontal_after.add(e.horizontal_m());
        }
      },
      [&](Measurement& m) {
        if (auto* h = std::get_if<GnssHeading>(&m)) h->heading_rad = rot::wrap_pi(h->heading_rad + baseline_error_rad);
        return true;
      });
  r.first_motion_s = summary.first_speed_2mps_s;
  r.stats = summary.stats;
  return r;
}

TEST(BaselineCheckScenario, SwappedAntennasAreFlaggedAndHeadingComesFromTheCourse) {
  const BaselineRun r = run_dual_antenna(rot::kPi);
  const std::uint64_t mismatches =
      r.stats.of(MeasurementKind::kGnssHeading).rejected_for(RejectReason::kBaselineMismatch);
  std::printf("180 deg baseline error: moving at %.2f s, flagged at %.2f s; heading RMS %.3f deg, horizontal "
              "RMS %.3f m from 30 s after the flag; %llu headings rejected as baseline_mismatch\n",
              r.first_motion_s, r.flagged_at_s, r.heading_after.value() * rot::kRadToDeg, r.horizontal_after.value(),
              static_cast<unsigned long long>(mismatches));
  ASSERT_GE(r.first_motion_s, 0.0);
  ASSERT_GE(r.flagged_at_s, r.first_motion_s);
  EXPECT_LE(r.flagged_at_s - r.first_motion_s, 10.0);
  EXPECT_GT(mismatches, 100u);
  EXPECT_GT(r.heading_after.n, 1000u);
  // Course-aligned and then held by GNSS velocity, position and NHC: the standalone-drive figures.
  EXPECT_LT(r.heading_after.value() * rot::kRadToDeg, 1.0);
  EXPECT_LT(r.horizontal_after.value(), 1.0);
}

TEST(BaselineCheckScenario, RightBaselineIsNeverFlagged) {
  const BaselineRun r = run_dual_antenna(0.0);
  EXPECT_LT(r.flagged_at_s, 0.0);
  EXPECT_EQ(r.stats.of(MeasurementKind::kGnssHeading).rejected_for(RejectReason::kBaselineMismatch), 0u);
}

}  // namespace
}  // namespace navfuse::filter

// Issue 17 "outputs say what is known": standing still with GNSS before any heading source (the
// static_start scenario, 60 s at rest with standalone fixes), the filter stays in vertical gyro.
// Its solution must carry the position of the fixes and the zero velocity of the stop as valid,
// with stds that cover the true error, and mark only the heading invalid, with the std of a
// heading nothing is known of (pi / sqrt(3)), not the near-zero std of the unestimated state.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/filter/scenario_harness.hpp"

namespace navfuse::filter {
namespace {

TEST(SolutionValidity, VerticalGyroCarriesPositionAndVelocityNotHeading) {
  const sim::Scenario s = sim::make_scenario("static_start");
  std::size_t checked = 0, covered = 0;
  double max_vel_err = 0.0;
  test::run_scenario(s, test::options_for(s), [&](const test::Epoch& e) {
    if (e.t_s < 5.0) return;  // levelled and placed at the fixes by then
    const NavSolution& sol = e.engine->solution();
    ASSERT_EQ(sol.mode, NavMode::kVerticalGyro) << e.t_s;
    const std::uint32_t v = sol.header.valid;
    EXPECT_NE(v & NavSolution::kValidPosition, 0u);
    EXPECT_NE(v & NavSolution::kValidPositionStd, 0u);
    EXPECT_NE(v & NavSolution::kValidVelocity, 0u);
    EXPECT_NE(v & NavSolution::kValidVelocityStd, 0u);
    EXPECT_NE(v & NavSolution::kValidAttitude, 0u);
    EXPECT_EQ(v & NavSolution::kValidHeading, 0u);
    EXPECT_NEAR(sol.att_std_rpy_rad.z(), rot::kPi / std::sqrt(3.0), 1e-12);
    ++checked;
    // Within 3 sigma horizontally (per axis) of the truth.
    const Eigen::Vector3d err = e.pos_err_ned_m;
    if (std::abs(err.x()) <= 3.0 * sol.pos_std_ned_m.x() && std::abs(err.y()) <= 3.0 * sol.pos_std_ned_m.y()) {
      ++covered;
    }
    max_vel_err = std::max(max_vel_err, e.vel_err_ned_mps.norm());
  });
  std::printf("vertical gyro: %zu epochs, position within 3 sigma at %.1f %%, max velocity error %.3f m/s\n",
              checked, 100.0 * static_cast<double>(covered) / static_cast<double>(checked), max_vel_err);
  EXPECT_GT(checked, 10000u);
  EXPECT_GE(static_cast<double>(covered), 0.99 * static_cast<double>(checked));
  EXPECT_LT(max_vel_err, 0.05);  // at rest: the zero-velocity updates
}

}  // namespace
}  // namespace navfuse::filter

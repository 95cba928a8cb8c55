// The jump-free output (filter/output_blend.hpp) on cases worked by hand: a correction above the
// threshold leaves the reported position where it was, the offset then decays as
// exp(-t / tau), and the reported std carries what is still pending; small corrections and a
// zero time constant pass straight through.
#include <cmath>

#include <gtest/gtest.h>

#include "core/geodesy/geodesy.hpp"
#include "filter/filter_core.hpp"
#include "filter/output_blend.hpp"
#include "filter/solution.hpp"

namespace navfuse::filter {
namespace {

// The north-east-down displacement of b from a, metres (small distances).
Eigen::Vector3d ned_from(const NavState& a, const NavState& b) { return -state_difference(a, b).segment<3>(sx::kPos); }

FilterCore core_at(double lat_deg, double lon_deg, double height_m) {
  FilterCore c;
  c.x.lat_rad = lat_deg * M_PI / 180.0;
  c.x.lon_rad = lon_deg * M_PI / 180.0;
  c.x.height_m = height_m;
  return c;
}

// Moves the filter's position by `ned_m` (as an update would).
void move(FilterCore& c, const Eigen::Vector3d& ned_m) {
  StateVector dx = StateVector::Zero();
  dx.segment<3>(sx::kPos) = -ned_m;
  inject_error(c.x, dx);
}

TEST(OutputBlend, ALargeCorrectionLeavesTheOutputWhereItWasThenDecays) {
  FilterOptions o;
  o.output_jump_blend_s = 0.25;
  o.output_jump_blend_min_m = 0.1;
  FilterCore c = core_at(40.0, -105.0, 1600.0);
  const NavState before = c.x;
  move(c, Eigen::Vector3d(0.4, -0.3, 0.0));  // a 0.5 m correction
  blend_position_jump(c, o, before);
  EXPECT_EQ(c.output_blend.jumps_blended, 1u);

  NavState out = c.x;
  Eigen::Matrix3d pos_cov = 0.0004 * Eigen::Matrix3d::Identity();
  apply_output_blend(c.output_blend, out, pos_cov);
  EXPECT_LT(ned_from(before, out).norm(), 1e-6);  // no jump in the output
  EXPECT_NEAR(pos_cov(0, 0), 0.0004 + 0.16, 1e-9);  // the pending 0.4 m north in the std
  EXPECT_NEAR(pos_cov(1, 1), 0.0004 + 0.09, 1e-9);

  // After 0.25 s (one time constant, in 5 ms steps) e^-1 of the correction is still pending.
  for (int i = 0; i < 50; ++i) decay_output_blend(c, o, 0.005);
  out = c.x;
  pos_cov.setZero();
  apply_output_blend(c.output_blend, out, pos_cov);
  const Eigen::Vector3d pending = ned_from(c.x, out);
  EXPECT_NEAR(pending.x(), -0.4 * std::exp(-1.0), 1e-6);
  EXPECT_NEAR(pending.y(), 0.3 * std::exp(-1.0), 1e-6);
  // And after 3 s it is gone.
  for (int i = 0; i < 600; ++i) decay_output_blend(c, o, 0.005);
  EXPECT_TRUE(c.output_blend.offset_ned_m.isZero(0.0));
}

TEST(OutputBlend, SmallCorrectionsAndAZeroTimeConstantPassStraightThrough) {
  FilterOptions o;
  o.output_jump_blend_s = 0.25;
  o.output_jump_blend_min_m = 0.1;
  FilterCore c = core_at(30.5, 114.3, 25.0);
  NavState before = c.x;
  move(c, Eigen::Vector3d(0.05, 0.05, 0.05));  // 8.7 cm: an ordinary RTK update
  blend_position_jump(c, o, before);
  EXPECT_TRUE(c.output_blend.offset_ned_m.isZero(0.0));
  o.output_jump_blend_s = 0.0;
  before = c.x;
  move(c, Eigen::Vector3d(1.0, 0.0, 0.0));
  blend_position_jump(c, o, before);
  EXPECT_TRUE(c.output_blend.offset_ned_m.isZero(0.0));
  EXPECT_EQ(c.output_blend.jumps_blended, 0u);
}

TEST(OutputBlend, TheSolutionReportsTheBlendedPosition) {
  FilterOptions o;
  FilterCore c = core_at(40.0, -105.0, 1600.0);
  c.mode.levelled = c.mode.heading_known = c.mode.position_known = true;
  c.mode.mode = NavMode::kNavigation;
  const NavState before = c.x;
  move(c, Eigen::Vector3d(0.0, 0.0, -0.6));  // up 0.6 m
  blend_position_jump(c, o, before);
  SolutionInputs in;
  capture_solution(c, o, Eigen::Matrix3d::Identity(), TimeSource::kGps, in);
  NavSolution s;
  fill_nav_solution(in, s);
  EXPECT_NEAR(s.height_m, before.height_m, 1e-6);
  EXPECT_NEAR(s.pos_std_ned_m.z(), 0.6, 1e-6);
}

}  // namespace
}  // namespace navfuse::filter

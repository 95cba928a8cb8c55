// The velocity that two fixes give for heading alignment (control/gnss_heading_alignment.hpp),
// against hand computation.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "filter/control/gnss_heading_alignment.hpp"

namespace navfuse::filter {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

GnssPosition fix_at(std::int64_t t_ns, const geo::Llh& llh, double std_m) {
  GnssPosition p;
  p.header.time_ns = t_ns;
  p.header.valid = GnssPosition::kValidPosition | GnssPosition::kValidHeight | GnssPosition::kValidCovariance;
  p.fix = GnssFixType::kRtkFixed;
  p.lat_rad = llh.lat_rad;
  p.lon_rad = llh.lon_rad;
  p.height_m = llh.height_m;
  p.cov_ned_m2 = Eigen::Matrix3d::Identity() * std_m * std_m;
  return p;
}

TEST(GnssHeadingAlignment, VelocityFromTwoFixesIsTheirDifferenceOverTheInterval) {
  const geo::Llh a{30.0 * kDeg, 114.0 * kDeg, 20.0};
  // 0.25 s later, 1.0 m north, 0.5 m east and 0.1 m up (llh_offset and ned_offset_m are exact
  // inverses through ECEF, checked in core's geodesy tests).
  const geo::Llh b = geo::llh_offset(a, Eigen::Vector3d(1.0, 0.5, -0.1));
  const FilterOptions o;
  const auto v = velocity_from_fixes(o, fix_at(1'000'000'000, a, 0.02), Eigen::Vector2d(1.0, 2.0),
                                     fix_at(1'250'000'000, b, 0.03), Eigen::Vector2d(3.0, 6.0));
  ASSERT_TRUE(v);
  EXPECT_NEAR(v->vel_ned_mps.x(), 4.0, 1e-6);
  EXPECT_NEAR(v->vel_ned_mps.y(), 2.0, 1e-6);
  EXPECT_NEAR(v->vel_ned_mps.z(), -0.4, 1e-6);
  // (0.02^2 + 0.03^2) / 0.25^2 = 0.0208 per axis.
  EXPECT_NEAR(v->cov_m2ps2(0, 0), 0.0208, 1e-12);
  EXPECT_NEAR(v->cov_m2ps2(2, 2), 0.0208, 1e-12);
  EXPECT_NEAR(v->cov_m2ps2(0, 1), 0.0, 1e-15);
  ASSERT_TRUE(v->force_integral_mps);
  EXPECT_EQ(*v->force_integral_mps, Eigen::Vector2d(2.0, 4.0));  // the interval's mean
  // The state at the later fix is half an interval past the mean: 4 m/s^2 * 0.125 s = 0.5 m/s.
  EXPECT_NEAR(v->state_reset_extra_var_m2ps2, 0.25, 1e-12);
}

TEST(GnssHeadingAlignment, FixesThatCannotBeDifferencedGiveNoVelocity) {
  const geo::Llh a{30.0 * kDeg, 114.0 * kDeg, 20.0};
  const FilterOptions o;
  const Eigen::Vector2d u = Eigen::Vector2d::Zero();
  const GnssPosition first = fix_at(1'000'000'000, a, 0.02);
  EXPECT_FALSE(velocity_from_fixes(o, first, u, first, u));                         // same time
  EXPECT_FALSE(velocity_from_fixes(o, fix_at(2'000'000'000, a, 0.02), u, first, u));  // backwards
  EXPECT_FALSE(velocity_from_fixes(o, first, u, fix_at(3'500'000'000, a, 0.02), u));  // 2.5 s apart
  GnssPosition other = fix_at(1'200'000'000, a, 0.02);
  other.receiver_id = 1;
  EXPECT_FALSE(velocity_from_fixes(o, first, u, other, u));  // another antenna
  GnssPosition no_height = fix_at(1'200'000'000, a, 0.02);
  no_height.header.valid &= ~GnssPosition::kValidHeight;
  EXPECT_FALSE(velocity_from_fixes(o, first, u, no_height, u));
  EXPECT_TRUE(velocity_from_fixes(o, first, u, fix_at(1'200'000'000, a, 0.02), u));
}

}  // namespace
}  // namespace navfuse::filter

// The non-holonomic constraint's noise when its point is only known to a std dev: the lever-arm
// term w_eb x d of the point's error, worked by hand for a yaw and a roll rate.
#include <gtest/gtest.h>

#include "filter/measurements/nonholonomic.hpp"

namespace navfuse::filter {
namespace {

TEST(Nonholonomic, AnUncertainPointAddsItsLeverArmTermToTheNoise) {
  NavState x;
  x.lat_rad = 0.8;
  x.vel_ned_mps = {10.0, 0.0, 0.0};  // level, heading north: body = NED
  const LocalEarth earth = LocalEarth::at(x.lat_rad, 0.0);
  const double p = 0.05, r = 0.2;  // roll and yaw rate relative to the earth (rad/s)
  const Eigen::Vector3d rate_b = earth.earth_rate_ned_rps + Eigen::Vector3d(p, 0.0, r);
  const StateView view(x, earth, rate_b, 0.0);
  const Eigen::Vector3d sigma(1.5, 0.5, 0.4);
  const Observation known = nonholonomic_observation(view, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.1, 0.2);
  const Observation guessed = nonholonomic_observation(view, Eigen::Vector3d::Zero(), sigma, 0.1, 0.2);
  // w x d for w = (p, 0, r): y = r dx - p dz, z = p dy. Variances r^2 sx^2 + p^2 sz^2 and
  // p^2 sy^2, covariance sum over axes of (r, 0, -p) (0, p, 0) sigma^2 = 0.
  EXPECT_NEAR(known.r(0, 0), 0.01, 1e-15);
  EXPECT_NEAR(known.r(1, 1), 0.04, 1e-15);
  EXPECT_NEAR(guessed.r(0, 0), 0.01 + r * r * 1.5 * 1.5 + p * p * 0.4 * 0.4, 1e-12);
  EXPECT_NEAR(guessed.r(1, 1), 0.04 + p * p * 0.5 * 0.5, 1e-12);
  EXPECT_NEAR(guessed.r(0, 1), 0.0, 1e-15);
  EXPECT_NEAR(guessed.r(1, 0), 0.0, 1e-15);
  // The prediction and its Jacobian do not depend on how well the point is known.
  EXPECT_EQ(guessed.residual, known.residual);
  EXPECT_EQ(guessed.h, known.h);
}

}  // namespace
}  // namespace navfuse::filter

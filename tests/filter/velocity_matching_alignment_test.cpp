// Heading by velocity matching against closed-form motion: the rotation between the provisional
// frame and north is recovered from the integrated specific force and the GNSS velocity, with a
// std that covers the error, and without assuming motion along the vehicle's x axis.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include "core/rotation/rotation.hpp"
#include "filter/velocity_matching_alignment.hpp"

namespace navfuse::filter {
namespace {

struct Result {
  std::optional<HeadingEstimate> estimate;
  int velocities = 0;  // GNSS velocities fed until the estimate came (or all)
};

// A walker-like horizontal motion: speed and direction change (a turn at `turn_rate_rps`); the
// provisional frame is the true one turned by -psi. GNSS velocity at 4 Hz with `vel_std_mps`.
// `sideways_rad` is the angle between the motion and the vehicle's x axis (irrelevant here).
Result run(double psi_rad, double turn_rate_rps, double vel_std_mps, double seconds, std::uint64_t seed = 7) {
  FilterOptions o;
  VelocityMatchWindow w;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, vel_std_mps);
  const double dt = 0.005;
  const Eigen::Matrix2d to_provisional = Eigen::Rotation2Dd(-psi_rad).toRotationMatrix();
  auto velocity = [&](double t) {
    const double speed = 1.2 * std::min(t, 1.0);  // accelerates from rest over 1 s
    const double course = 0.3 + turn_rate_rps * t;
    return Eigen::Vector2d(speed * std::cos(course), speed * std::sin(course));
  };
  Result r;
  auto feed = [&](double t) {
    const Eigen::Vector2d v = velocity(t) + Eigen::Vector2d(noise(rng), noise(rng));
    ++r.velocities;
    return add_velocity_match(w, o, static_cast<std::int64_t>(std::llround(t * 1e9)), v,
                              vel_std_mps * vel_std_mps);
  };
  feed(0.0);  // the window starts at rest
  for (int k = 1; k * dt <= seconds + 1e-9; ++k) {
    const double t = k * dt;
    // Specific force in the provisional frame (C_nb = identity there): the velocity change.
    const Eigen::Vector2d dv_n = velocity(t) - velocity(t - dt);
    const Eigen::Vector2d dv_p = to_provisional * dv_n;
    accumulate_velocity_match(w, Eigen::Matrix3d::Identity(), Eigen::Vector3d(dv_p.x(), dv_p.y(), -9.8 * dt));
    if (k % 50 == 0) {
      if (auto e = feed(t)) {
        r.estimate = e;
        return r;
      }
    }
  }
  return r;
}

TEST(VelocityMatching, RecoversTheRotationWithinItsStd) {
  for (double psi_deg : {-170.0, -60.0, 0.0, 35.0, 120.0}) {
    const Result r = run(psi_deg * rot::kDegToRad, 0.4, 0.05, 6.0);
    ASSERT_TRUE(r.estimate) << psi_deg;
    const double err = rot::wrap_pi(r.estimate->rotation_rad - psi_deg * rot::kDegToRad);
    EXPECT_LT(std::abs(err), 3.0 * r.estimate->std_rad) << psi_deg;
    EXPECT_LE(r.estimate->std_rad, FilterOptions{}.velocity_match_max_std_rad);
  }
  // An RTK-grade velocity (1 cm/s) pins it to about a degree at the first estimate.
  const Result rtk = run(100.0 * rot::kDegToRad, 0.4, 0.01, 6.0);
  ASSERT_TRUE(rtk.estimate);
  EXPECT_LT(std::abs(rot::wrap_pi(rtk.estimate->rotation_rad - 100.0 * rot::kDegToRad)), 2.0 * rot::kDegToRad);
}

TEST(VelocityMatching, WaitsForMinimumSamplesAndExcitation) {
  // Constant velocity from the start: no acceleration, no information, no heading.
  FilterOptions o;
  VelocityMatchWindow w;
  const Eigen::Vector2d v(1.0, 0.5);
  for (int k = 0; k < 20; ++k) {
    EXPECT_FALSE(add_velocity_match(w, o, k * 250'000'000LL, v, 0.05 * 0.05)) << k;
  }
  // Accelerating: the first estimate comes only once min_samples velocities follow the start.
  const Result r = run(0.5, 0.4, 0.02, 6.0);
  ASSERT_TRUE(r.estimate);
  EXPECT_GE(r.velocities, 1 + o.velocity_match_min_samples);
}

TEST(VelocityMatching, NoisierVelocityGivesLargerStd) {
  const Result quiet = run(1.0, 0.4, 0.01, 6.0, 3);
  const Result noisy = run(1.0, 0.4, 0.10, 6.0, 3);
  ASSERT_TRUE(quiet.estimate);
  if (noisy.estimate) {
    EXPECT_GT(noisy.estimate->std_rad, quiet.estimate->std_rad);
  }
}

}  // namespace
}  // namespace navfuse::filter

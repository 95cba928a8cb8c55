// Attitude conventions (DESIGN.md): q_nb Hamilton, vehicle FRD -> NED, Euler 3-2-1. Each
// convention is pinned by a hand-computed example; conversions round-trip.
#include "core/rotation/rotation.hpp"

#include <gtest/gtest.h>

#include <random>

namespace navfuse::rot {
namespace {

constexpr double kDeg = kDegToRad;

TEST(Rotation, Yaw90MapsForwardToEast) {
  const Eigen::Quaterniond q = quat_from_rpy({0, 0, 90 * kDeg});
  const Eigen::Vector3d fwd_ned = q * Eigen::Vector3d::UnitX();
  EXPECT_TRUE(fwd_ned.isApprox(Eigen::Vector3d(0, 1, 0), 1e-12));
  // Right wing points south.
  EXPECT_TRUE((q * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
}

TEST(Rotation, PositivePitchIsNoseUpPositiveRollIsRightWingDown) {
  const Eigen::Vector3d nose = quat_from_rpy({0, 10 * kDeg, 0}) * Eigen::Vector3d::UnitX();
  EXPECT_LT(nose.z(), 0.0);  // up is -z in NED
  const Eigen::Vector3d right = quat_from_rpy({10 * kDeg, 0, 0}) * Eigen::Vector3d::UnitY();
  EXPECT_GT(right.z(), 0.0);
}

TEST(Rotation, DcmHandComputed) {
  // yaw 30, pitch 0, roll 0: C_nb = Rz(30).
  const Eigen::Matrix3d c = dcm_from_rpy({0, 0, 30 * kDeg});
  const double s = 0.5, co = std::sqrt(3.0) / 2.0;
  Eigen::Matrix3d expected;
  expected << co, -s, 0, s, co, 0, 0, 0, 1;
  EXPECT_TRUE(c.isApprox(expected, 1e-12));
}

TEST(Rotation, QuaternionDcmAndEulerAgreeAndRoundTrip) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d rpy(u(rng) * kPi, u(rng) * 0.49 * kPi, u(rng) * kPi);
    const Eigen::Quaterniond q = quat_from_rpy(rpy);
    EXPECT_TRUE(q.toRotationMatrix().isApprox(dcm_from_rpy(rpy), 1e-12));
    const Eigen::Vector3d back = rpy_from_quat(q);
    EXPECT_NEAR(back.x(), rpy.x(), 1e-9);
    EXPECT_NEAR(back.y(), rpy.y(), 1e-9);
    EXPECT_NEAR(wrap_pi(back.z() - rpy.z()), 0.0, 1e-9);
  }
}

TEST(Rotation, GimbalLockReportsZeroRoll) {
  const Eigen::Vector3d rpy = rpy_from_dcm(dcm_from_rpy({0.3, 90 * kDeg, 0.5}));
  EXPECT_NEAR(rpy.x(), 0.0, 1e-12);
  EXPECT_NEAR(rpy.y(), 90 * kDeg, 1e-6);
  // Only yaw - roll is observable at +90 pitch.
  EXPECT_NEAR(wrap_pi(rpy.z() - (0.5 - 0.3)), 0.0, 1e-6);
}

TEST(Rotation, RotationVectorExponentialMap) {
  const Eigen::Vector3d rv(0.1, -0.2, 0.3);
  const Eigen::Quaterniond q = quat_from_rotvec(rv);
  EXPECT_TRUE(q.isApprox(Eigen::Quaterniond(Eigen::AngleAxisd(rv.norm(), rv.normalized())), 1e-14));
  EXPECT_TRUE(rotvec_from_quat(q).isApprox(rv, 1e-14));
  // Tiny angles keep full relative precision.
  const Eigen::Vector3d tiny(1e-10, 2e-10, -3e-10);
  EXPECT_TRUE(rotvec_from_quat(quat_from_rotvec(tiny)).isApprox(tiny, 1e-9));
  EXPECT_NEAR(quat_from_rotvec(tiny).norm(), 1.0, 1e-16);
}

TEST(Rotation, SkewIsCrossProduct) {
  const Eigen::Vector3d a(1, 2, 3), b(-4, 5, 0.5);
  EXPECT_TRUE((skew(a) * b).isApprox(a.cross(b)));
}

TEST(Rotation, FrameSwaps) {
  EXPECT_EQ(enu_from_ned({1, 2, 3}), Eigen::Vector3d(2, 1, -3));
  EXPECT_EQ(ned_from_enu(enu_from_ned({1, 2, 3})), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(flu_from_frd({1, 2, 3}), Eigen::Vector3d(1, -2, -3));
}

TEST(Rotation, FusionEngineEnuYawOfNedYaw90IsZero) {
  // Vehicle facing east: NED yaw 90 deg. In ENU/FLU (FusionEngine Pose) yaw is measured from
  // east counter-clockwise, so it is 0; heading = 90 - yaw_enu = 90.
  const Eigen::Quaterniond q_enu = quat_enu_flu_from_ned_frd(quat_from_rpy({0, 0, 90 * kDeg}));
  EXPECT_NEAR(rpy_from_quat(q_enu).z(), 0.0, 1e-12);
  // NED yaw 30 (NNE) -> ENU yaw 60; roll keeps its sign, pitch flips (FLU y points left).
  const Eigen::Vector3d enu = rpy_from_quat(quat_enu_flu_from_ned_frd(quat_from_rpy({5 * kDeg, 7 * kDeg, 30 * kDeg})));
  EXPECT_NEAR(enu.z(), 60 * kDeg, 1e-12);
  EXPECT_NEAR(enu.x(), 5 * kDeg, 1e-12);
  EXPECT_NEAR(enu.y(), -7 * kDeg, 1e-12);
  // And back.
  const Eigen::Quaterniond q = quat_from_rpy({0.1, -0.2, 2.5});
  EXPECT_TRUE(quat_ned_frd_from_enu_flu(quat_enu_flu_from_ned_frd(q)).isApprox(q, 1e-12) ||
              quat_ned_frd_from_enu_flu(quat_enu_flu_from_ned_frd(q)).coeffs().isApprox(-q.coeffs(), 1e-12));
}

TEST(Rotation, Wrap) {
  EXPECT_NEAR(wrap_pi(3 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_NEAR(wrap_pi(-3 * kPi / 2), kPi / 2, 1e-15);
  EXPECT_NEAR(wrap_pi(kPi), -kPi, 1e-15);
  EXPECT_NEAR(wrap_two_pi(-kPi / 2), 3 * kPi / 2, 1e-15);
}

}  // namespace
}  // namespace navfuse::rot

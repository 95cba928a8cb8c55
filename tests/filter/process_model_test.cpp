// The covariance step against the textbook dense form: Phi = I + F T + (F T)^2 / 2 and
// P' = Phi P Phi^T + Q T + (F Q + Q F^T) T^2 / 2 (Groves 2nd ed. §3.2.3 / §14.2.4), computed here
// with plain full-size matrix products. The filter's version works on the non-zero rows of F
// only; both must agree to rounding.
#include <cstring>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/cpu/cpu_features.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/active_dimension.hpp"
#include "filter/process_model.hpp"

namespace navfuse::filter {
namespace {

Covariance random_covariance(int n, std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = g(rng) * (0.1 + i * 0.05);
  Covariance p = Covariance::Zero();
  p.topLeftCorner(n, n) = a * a.transpose() + Eigen::MatrixXd::Identity(n, n) * 1e-3;
  return p;
}

Covariance dense_reference(const Covariance& p0, int n, const SystemRows& rows, const StateVector& q, double t) {
  Covariance f = Covariance::Zero();  // F with its zero rows written out
  f.topRows<sx::kDynamicCount>() = rows;
  const Eigen::MatrixXd ft = f.topLeftCorner(n, n) * t;
  const Eigen::MatrixXd phi = Eigen::MatrixXd::Identity(n, n) + ft + 0.5 * ft * ft;
  const Eigen::MatrixXd qm = q.head(n).asDiagonal();
  const Eigen::MatrixXd qd = qm * t + (f.topLeftCorner(n, n) * qm + qm * f.topLeftCorner(n, n).transpose()) * (0.5 * t * t);
  Covariance out = p0;
  out.topLeftCorner(n, n) = phi * p0.topLeftCorner(n, n) * phi.transpose() + qd;
  return out;
}

TEST(ProcessModel, SystemMatrixHasTheClosedFormBlocks) {
  NavState x;
  x.lat_rad = 0.7;
  x.height_m = 120.0;
  x.vel_ned_mps = {12.0, -3.0, 0.4};
  x.q_nb = rot::quat_from_rpy({0.05, -0.02, 1.1});
  ProcessAccumulator step;
  step.dt_s = 0.05;
  step.dtheta_rad = {0.001, -0.002, 0.01};
  step.dvel_mps = {0.05, 0.02, -0.49};
  const SystemRows f = system_matrix(x, LocalEarth::at(x.lat_rad, x.height_m), step).dense();
  const Eigen::Matrix3d c_nb = x.q_nb.toRotationMatrix();
  // The phi-angle model (Shin 2005 ch. 3): dr' = dv, dv' contains -C_nb db_a, phi' contains
  // C_nb db_g, and the tilt coupling [f^n x] with f^n = C_nb f^b.
  EXPECT_TRUE((f.block<3, 3>(sx::kPos, sx::kVel).isIdentity(0.0)));
  EXPECT_TRUE((f.block<3, 3>(sx::kVel, sx::kAccelBias).isApprox(-c_nb, 1e-15)));
  EXPECT_TRUE((f.block<3, 3>(sx::kAtt, sx::kGyroBias).isApprox(c_nb, 1e-15)));
  const Eigen::Vector3d f_n = c_nb * (step.dvel_mps / step.dt_s);
  EXPECT_NEAR(f(sx::kVel + 0, sx::kAtt + 1), -f_n.z(), 1e-12);
  EXPECT_NEAR(f(sx::kVel + 1, sx::kAtt + 0), f_n.z(), 1e-12);
}

TEST(ProcessModel, SparseStepMatchesDenseFormForEveryActiveDimension) {
  std::mt19937 rng(7);
  NavState x;
  x.lat_rad = -0.6;
  x.height_m = 850.0;
  x.vel_ned_mps = {-20.0, 15.0, -1.0};
  x.q_nb = rot::quat_from_rpy({-0.1, 0.08, -2.5});
  ProcessAccumulator step;
  step.dt_s = 0.05;
  step.dtheta_rad = {0.02, 0.004, -0.03};
  step.dvel_mps = {0.3, -0.1, -0.5};
  const LocalEarth earth = LocalEarth::at(x.lat_rad, x.height_m);
  StateVector q;
  for (int i = 0; i < sx::kCount; ++i) q(i) = 1e-6 * (1 + i);
  const SystemRows f = system_matrix(x, earth, step).dense();
  for (int n : kActiveDimensions) {
    SCOPED_TRACE(n);
    const Covariance p0 = random_covariance(n, rng);
    Covariance p = p0;
    propagate_covariance(p, n, x, earth, step, q);
    const Covariance expected = dense_reference(p0, n, f, q, step.dt_s);
    EXPECT_LT((p - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
    EXPECT_EQ((p - p.transpose()).cwiseAbs().maxCoeff(), 0.0);
  }
}

// The AVX2 build of the step rounds every entry as the baseline build does (no FMA, same order
// of operations), so the two give identical bits, and replay outputs do not depend on the CPU.
TEST(ProcessModel, Avx2AndBaselineStepsGiveIdenticalBits) {
  if (!cpu::has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU: only the baseline step runs";
  std::mt19937 rng(11);
  NavState x;
  x.lat_rad = 0.9;
  x.height_m = -30.0;
  x.vel_ned_mps = {31.0, 4.0, 0.2};
  x.q_nb = rot::quat_from_rpy({0.2, -0.15, 0.7});
  ProcessAccumulator step;
  step.dt_s = 0.02;
  step.dtheta_rad = {-0.01, 0.003, 0.02};
  step.dvel_mps = {0.1, 0.05, -0.2};
  const LocalEarth earth = LocalEarth::at(x.lat_rad, x.height_m);
  StateVector q;
  for (int i = 0; i < sx::kCount; ++i) q(i) = 3e-7 * (2 + i);
  for (int n : kActiveDimensions) {
    SCOPED_TRACE(n);
    const Covariance p0 = random_covariance(n, rng);
    Covariance fastest = p0, baseline = p0;
    propagate_covariance(fastest, n, x, earth, step, q, CovarianceKernel::kFastest);
    propagate_covariance(baseline, n, x, earth, step, q, CovarianceKernel::kBaseline);
    EXPECT_FALSE(fastest == p0);  // the step did something
    EXPECT_EQ(std::memcmp(fastest.data(), baseline.data(), sizeof(double) * fastest.size()), 0);
  }
}

// Every state selection's active dimension has a compiled kernel (with_active_dimension falls
// back to the full set for any other n, which would be correct but slow).
TEST(ProcessModel, EveryStateSelectionHasAFixedSizeKernel) {
  for (unsigned bits = 0; bits < 32; ++bits) {
    StateSelection s;
    s.wheel_scale = (bits & 1u) != 0;
    s.mounting = (bits & 2u) != 0;
    s.gnss_lever_arm = (bits & 4u) != 0;
    s.gyro_scale = (bits & 8u) != 0;
    s.accel_scale = (bits & 16u) != 0;
    const int n = s.active_dimension();
    int dispatched = 0;
    with_active_dimension(n, [&](auto dim) { dispatched = decltype(dim)::value; });
    EXPECT_EQ(dispatched, n) << "selection bits " << bits;
  }
}

// The sparse F list refuses entries the covariance step could not index: a row without
// dynamics, a column outside the block it is built for, or more entries than it holds.
TEST(ProcessModel, SystemMatrixEntriesAreBoundsChecked) {
  SystemMatrix f;
  EXPECT_THROW(f.push(sx::kDynamicCount, 0, 1.0), std::logic_error);
  EXPECT_THROW(f.push(-1, 0, 1.0), std::logic_error);
  EXPECT_THROW(f.push(0, sx::kCount, 1.0), std::logic_error);
  EXPECT_THROW(f.push(0, sx::kCoreCount, 1.0, sx::kCoreCount), std::logic_error);
  EXPECT_EQ(f.count, 0);
  for (int i = 0; i < SystemMatrix::kMaxEntries; ++i) f.push(i % sx::kDynamicCount, i % sx::kCount, 1.0);
  EXPECT_THROW(f.push(0, 0, 1.0), std::logic_error);
  EXPECT_EQ(f.count, SystemMatrix::kMaxEntries);
  // What system_matrix builds fits, with room to spare.
  NavState x;
  x.lat_rad = 0.5;
  x.vel_ned_mps = {10.0, 5.0, 1.0};
  x.q_nb = rot::quat_from_rpy({0.1, 0.2, 0.3});
  ProcessAccumulator step;
  step.dt_s = 0.01;
  step.dtheta_rad = {0.001, 0.002, 0.003};
  step.dvel_mps = {0.01, 0.02, -0.098};
  EXPECT_LE(system_matrix(x, LocalEarth::at(x.lat_rad, 0.0), step).count, SystemMatrix::kMaxEntries);
}

}  // namespace
}  // namespace navfuse::filter

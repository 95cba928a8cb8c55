// The Joseph-form update against hand-computed 1-D and 2-D cases and against the textbook
// (I - K H) P (I - K H)^T + K R K^T with full matrices; the chi-square gate; covariance resets.
#include <gtest/gtest.h>

#include <random>

#include <Eigen/LU>

#include "filter/ekf.hpp"

namespace navfuse::filter {
namespace {

Ekf make_ekf() {
  Ekf e;
  e.n = sx::kCoreCount;
  e.p.topLeftCorner(e.n, e.n).setIdentity();
  return e;
}

TEST(Ekf, ScalarUpdateMatchesHandComputation) {
  // P = 4, R = 1, residual 2: K = 4/5, dx = 1.6, P' = 4 * 1 / 5 = 0.8.
  Ekf e = make_ekf();
  e.p(0, 0) = 4.0;
  Observation obs(1);
  obs.h(0, sx::kPos) = 1.0;
  obs.r(0, 0) = 1.0;
  obs.residual(0) = 2.0;
  const UpdateResult r = e.update(obs, 0.0);
  ASSERT_TRUE(r.accepted);
  EXPECT_NEAR(r.dx(0), 1.6, 1e-12);
  EXPECT_NEAR(e.p(0, 0), 0.8, 1e-12);
  EXPECT_NEAR(r.nis, 4.0 / 5.0, 1e-12);
  EXPECT_NEAR(e.p(1, 1), 1.0, 1e-15);  // untouched, uncorrelated state
}

TEST(Ekf, TwoStateUpdateMatchesHandComputation) {
  // P = [[2, 1], [1, 3]], H = [1 1], R = 0.5: S = 7.5, K = [3, 4] / 7.5,
  // P' = P - K S K^T = [[0.8, -0.6], [-0.6, 0.8667]]; residual 1.5 gives dx = [0.6, 0.8].
  Ekf e = make_ekf();
  e.p(0, 0) = 2.0;
  e.p(0, 1) = e.p(1, 0) = 1.0;
  e.p(1, 1) = 3.0;
  Observation obs(1);
  obs.h(0, 0) = 1.0;
  obs.h(0, 1) = 1.0;
  obs.r(0, 0) = 0.5;
  obs.residual(0) = 1.5;
  const UpdateResult r = e.update(obs, 0.0);
  ASSERT_TRUE(r.accepted);
  EXPECT_NEAR(r.dx(0), 0.6, 1e-12);
  EXPECT_NEAR(r.dx(1), 0.8, 1e-12);
  EXPECT_NEAR(e.p(0, 0), 0.8, 1e-12);
  EXPECT_NEAR(e.p(0, 1), -0.6, 1e-12);
  EXPECT_NEAR(e.p(1, 0), -0.6, 1e-12);
  EXPECT_NEAR(e.p(1, 1), 3.0 - 16.0 / 7.5, 1e-12);
}

TEST(Ekf, JosephMatchesFullMatrixFormOnRandomCase) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  Ekf e;
  e.n = 21;
  Eigen::MatrixXd a(e.n, e.n);
  for (int i = 0; i < e.n; ++i) for (int j = 0; j < e.n; ++j) a(i, j) = n(rng);
  e.p.topLeftCorner(e.n, e.n) = a * a.transpose() + Eigen::MatrixXd::Identity(e.n, e.n);
  Observation obs(3);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < e.n; ++j) obs.h(i, j) = n(rng);
    obs.residual(i) = n(rng);
  }
  obs.r << 0.5, 0.1, 0.0, 0.1, 0.7, 0.2, 0.0, 0.2, 0.9;

  const Eigen::MatrixXd p = e.p.topLeftCorner(e.n, e.n);
  const Eigen::MatrixXd h = obs.h.leftCols(e.n);
  const Eigen::MatrixXd r = obs.r;
  const Eigen::MatrixXd k = p * h.transpose() * (h * p * h.transpose() + r).inverse();
  const Eigen::MatrixXd ikh = Eigen::MatrixXd::Identity(e.n, e.n) - k * h;
  const Eigen::MatrixXd expected = ikh * p * ikh.transpose() + k * r * k.transpose();
  const Eigen::VectorXd expected_dx = k * obs.residual;

  const UpdateResult res = e.update(obs, 0.0);
  ASSERT_TRUE(res.accepted);
  EXPECT_LT((e.p.topLeftCorner(e.n, e.n) - expected).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((res.dx.head(e.n) - expected_dx).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((e.p - e.p.transpose()).cwiseAbs().maxCoeff(), 1e-15);  // exactly symmetric
}

TEST(Ekf, GateRejectsWithoutTouchingCovariance) {
  Ekf e = make_ekf();
  Observation obs(1);
  obs.h(0, sx::kPos) = 1.0;
  obs.r(0, 0) = 1.0;
  obs.residual(0) = 10.0;  // NIS = 100 / 2 = 50 > 15.14
  const Covariance before = e.p;
  const UpdateResult r = e.update(obs, 15.14);
  EXPECT_FALSE(r.accepted);
  EXPECT_NEAR(r.nis, 50.0, 1e-12);
  EXPECT_EQ(e.p, before);
  obs.residual(0) = 5.0;  // NIS = 12.5 passes
  EXPECT_TRUE(e.update(obs, 15.14).accepted);
}

TEST(Ekf, KeepRowsSelectsValidAxes) {
  Observation obs(3);
  for (int i = 0; i < 3; ++i) {
    obs.residual(i) = i + 1.0;
    obs.h(i, i) = 10.0 * (i + 1);
    for (int j = 0; j < 3; ++j) obs.r(i, j) = 100.0 * i + j;
  }
  obs.keep_rows(0b101);
  ASSERT_EQ(obs.rows(), 2);
  EXPECT_EQ(obs.residual(0), 1.0);
  EXPECT_EQ(obs.residual(1), 3.0);
  EXPECT_EQ(obs.h(1, 2), 30.0);
  EXPECT_EQ(obs.r(0, 1), 2.0);
  EXPECT_EQ(obs.r(1, 0), 200.0);
  EXPECT_EQ(obs.r(1, 1), 202.0);
}

TEST(Ekf, ResetStatesDecorrelates) {
  Ekf e = make_ekf();
  e.p(0, 7) = e.p(7, 0) = 0.3;
  e.reset_states(sx::kAtt, 3, 4.0);
  EXPECT_EQ(e.p(0, 7), 0.0);
  EXPECT_EQ(e.p(7, 0), 0.0);
  EXPECT_EQ(e.p(7, 7), 4.0);
}

}  // namespace
}  // namespace navfuse::filter

// The GNSS measurement-noise multiplier (control/measurement_noise_adaptation.hpp) on synthetic
// innovation sequences whose statistics are known: residuals drawn with 2x the reported std give
// a multiplier near 4; residuals as reported, or a gate that passes them, leave R as reported; a
// persistent offset (a filter that lags, P's problem) does not move R.
#include <gtest/gtest.h>

#include <random>

#include "filter/control/measurement_noise_adaptation.hpp"

namespace navfuse::filter {
namespace {

constexpr double kGate3d = 21.11;

Ekf small_p() {
  Ekf e;
  e.n = sx::kCoreCount;
  e.p.setZero();
  e.p.topLeftCorner(sx::kCoreCount, sx::kCoreCount).diagonal().setConstant(1e-8);  // P far below R
  return e;
}

Observation position_obs(const Eigen::Vector3d& residual, double reported_std_m) {
  Observation obs(3);
  obs.h.block<3, 3>(0, sx::kPos).setIdentity();
  obs.r = Eigen::Matrix3d::Identity() * reported_std_m * reported_std_m;
  obs.residual = residual;
  return obs;
}

// Feeds `n` white residuals of std `true_std_m` against a reported `reported_std_m`.
double scale_after_white(double true_std_m, double reported_std_m, int n, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, true_std_m);
  const Ekf ekf = small_p();
  NoiseScaleWindow w;
  AdaptationOptions a;
  double scale = 1.0;
  for (int k = 0; k < n; ++k) {
    scale = update_noise_scale(w, ekf, position_obs({normal(rng), normal(rng), normal(rng)}, reported_std_m), a,
                               kGate3d);
  }
  return scale;
}

TEST(MeasurementNoiseAdaptation, OptimisticStdIsScaledToTheRealSpread) {
  // 5 mm reported, 2 cm real (RTKLIB's fixed-solution figures against a moving car's errors):
  // variance ratio 16; the gate at 21.11 rejects most such fixes, so R is adapted. A median over
  // 32 samples scatters by ~25 %.
  const double s = scale_after_white(0.02, 0.005, 200);
  EXPECT_GT(s, 16.0 * 0.6);
  EXPECT_LT(s, 16.0 * 1.6);
  // Twice the std: ratio 4 (about 12 % of the fixes outside the gate with R as reported).
  const double s2 = scale_after_white(0.02, 0.01, 400, 11);
  EXPECT_GT(s2, 4.0 * 0.6);
  EXPECT_LT(s2, 4.0 * 1.6);
}

TEST(MeasurementNoiseAdaptation, HonestStdIsLeftAsReported) {
  EXPECT_EQ(scale_after_white(0.02, 0.02, 400), 1.0);
  // 1.3x: the reported R gates out under 5 % of the fixes: left as it is.
  EXPECT_EQ(scale_after_white(0.026, 0.02, 400, 3), 1.0);
}

TEST(MeasurementNoiseAdaptation, FewSamplesAndPersistentOffsetsDoNotMoveR) {
  const Ekf ekf = small_p();
  AdaptationOptions a;
  NoiseScaleWindow w;
  // Seven wild residuals: below the minimum count.
  for (int k = 0; k < NoiseScaleWindow::kMinSamples - 1; ++k) {
    EXPECT_EQ(update_noise_scale(w, ekf, position_obs({0.1, -0.1, 0.05}, 0.01), a, kGate3d), 1.0);
  }
  // The same offset every time: the filter lags the aid (lag-1 correlation 1), not an R problem.
  for (int k = 0; k < 40; ++k) {
    EXPECT_EQ(update_noise_scale(w, ekf, position_obs({0.1, -0.1, 0.05}, 0.01), a, kGate3d), 1.0) << k;
  }
  // Switched off: R as reported whatever the residuals.
  AdaptationOptions off;
  off.enabled = false;
  NoiseScaleWindow w2;
  for (int k = 0; k < 40; ++k) {
    EXPECT_EQ(update_noise_scale(w2, ekf, position_obs({(k % 2 ? 0.1 : -0.1), 0.0, 0.0}, 0.01), off, kGate3d), 1.0);
  }
}

TEST(MeasurementNoiseAdaptation, CappedByTheOption) {
  const Ekf ekf = small_p();
  AdaptationOptions a;
  a.max_measurement_noise_scale = 9.0;
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0.0, 0.05);
  NoiseScaleWindow w;
  double s = 1.0;
  for (int k = 0; k < 200; ++k) s = update_noise_scale(w, ekf, position_obs({normal(rng), normal(rng), normal(rng)}, 0.005), a, kGate3d);
  EXPECT_EQ(s, 9.0);  // the estimate is ~100
  EXPECT_EQ(w.max_scale, 9.0);
}

}  // namespace
}  // namespace navfuse::filter

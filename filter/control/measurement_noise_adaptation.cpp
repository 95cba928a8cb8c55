#include "filter/control/measurement_noise_adaptation.hpp"

#include <algorithm>
#include <cmath>

namespace navfuse::filter {
namespace {

// Median of chi-square(m) / m, m = 1, 2, 3 (chi-square quantile tables, e.g. Abramowitz & Stegun
// Table 26.8: medians 0.4549, 1.3863, 2.3660).
double chi2_median_over_mean(int m) {
  switch (m) {
    case 1: return 0.4549;
    case 2: return 1.3863 / 2.0;
    default: return 2.3660 / 3.0;
  }
}

// Above this lag-1 correlation the residuals say the filter lags (P too small), not that R is.
constexpr double kMaxLag1Correlation = 0.3;
// The share of the window the reported R would gate out before R is adapted at all.
constexpr double kMinGatedFraction = 0.05;

}  // namespace

double update_noise_scale(NoiseScaleWindow& w, const Ekf& ekf, const Observation& obs, const AdaptationOptions& a,
                          double gate) {
  if (!a.enabled || obs.rows() == 0) return w.scale;
  const InnovationMoments stats = ekf.innovation_moments(obs);
  const double spread = stats.spread, nis = stats.nis;
  const double noise = obs.r.trace();
  if (!(noise > 0.0) || !std::isfinite(spread)) return w.scale;
  const double rho = (obs.residual.squaredNorm() - spread) / noise;
  if (!std::isfinite(rho)) return w.scale;
  w.rho[static_cast<std::size_t>(w.next)] = rho;
  auto& r = w.residual[static_cast<std::size_t>(w.next)];
  r = {};
  for (int i = 0; i < std::min(obs.rows(), 3); ++i) r[static_cast<std::size_t>(i)] = obs.residual(i);
  w.gated[static_cast<std::size_t>(w.next)] = !(nis <= gate);
  w.next = (w.next + 1) % NoiseScaleWindow::kCapacity;
  w.count = std::min(w.count + 1, NoiseScaleWindow::kCapacity);
  if (w.count < NoiseScaleWindow::kMinSamples) return w.scale;

  // Lag-1 correlation of the residuals, oldest to newest (Mehra 1970, "On the identification of
  // variances and adaptive Kalman filtering", IEEE TAC 15(2): an optimal filter's innovations are
  // white). A filter whose P is too small lags behind the aid: its residuals persist from one
  // update to the next (positive correlation), and that is innovation_adaptation's to repair. R
  // too small makes the filter jump to every fix: the next residual is the difference of two
  // noises (negative correlation). Only then is the excess the aid's.
  double lag1 = 0.0, power = 0.0;
  for (int k = 0; k < w.count; ++k) {
    const int i = (w.next - w.count + k + NoiseScaleWindow::kCapacity) % NoiseScaleWindow::kCapacity;
    const auto& a = w.residual[static_cast<std::size_t>(i)];
    power += a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    if (k == 0) continue;
    const auto& b = w.residual[static_cast<std::size_t>((i + NoiseScaleWindow::kCapacity - 1) % NoiseScaleWindow::kCapacity)];
    lag1 += a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  if (power > 0.0 && lag1 / power > kMaxLag1Correlation) return w.scale;
  int gated = 0;
  for (int k = 0; k < w.count; ++k) gated += w.gated[static_cast<std::size_t>(k)] ? 1 : 0;
  if (gated < kMinGatedFraction * w.count) {
    w.scale = 1.0;
    return w.scale;
  }

  std::array<double, NoiseScaleWindow::kCapacity> sorted = w.rho;
  auto mid = sorted.begin() + (w.count - 1) / 2;  // the lower median
  std::nth_element(sorted.begin(), mid, sorted.begin() + w.count);
  const double estimate = *mid / chi2_median_over_mean(std::min(obs.rows(), 3));
  w.scale = std::clamp(estimate, 1.0, a.max_measurement_noise_scale);
  w.max_scale = std::max(w.max_scale, w.scale);
  return w.scale;
}

}  // namespace navfuse::filter

#include "filter/control/innovation_adaptation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "filter/filter_core.hpp"
#include "filter/smoother/forward_record.hpp"

namespace navfuse::filter {

void InnovationWindow::push(const Sample& s) {
  samples[static_cast<std::size_t>(next)] = s;
  next = (next + 1) % kCapacity;
  count = std::min(count + 1, kCapacity);
}

std::optional<InnovationWindow::Medians> InnovationWindow::recent_medians(std::int64_t now_ns, double window_s,
                                                                          int min_samples, double large_nis) const {
  std::array<double, kCapacity> nis{};
  std::array<double, kCapacity> lambda{};
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();  // over the large residuals only
  double sum_sq = 0.0;
  int n = 0, large = 0;
  for (int i = 0; i < count; ++i) {
    const Sample& s = samples[static_cast<std::size_t>(i)];
    const double age_s = static_cast<double>(now_ns - s.time_ns) * 1e-9;
    if (age_s < 0.0 || age_s > window_s) continue;
    nis[static_cast<std::size_t>(n)] = s.nis_per_dim;
    lambda[static_cast<std::size_t>(n)] = s.lambda;
    if (s.nis_per_dim >= large_nis) {
      const Eigen::Vector3d r(s.residual[0], s.residual[1], s.residual[2]);
      sum += r;
      sum_sq += r.squaredNorm();
      ++large;
    }
    ++n;
  }
  if (n < std::max(min_samples, 1)) return std::nullopt;
  // The lower median: with an even count, a single large sample still cannot decide.
  const auto median = [n](std::array<double, kCapacity>& v) {
    auto mid = v.begin() + (n - 1) / 2;
    std::nth_element(v.begin(), mid, v.begin() + n);
    return *mid;
  };
  bool agree = false;
  if (large > 0) {
    const Eigen::Vector3d mean = sum / large;
    agree = mean.squaredNorm() > std::max(0.0, sum_sq / large - mean.squaredNorm());
  }
  return Medians{median(nis), median(lambda), agree};
}

InnovationWindow::Sample innovation_sample(const Ekf& ekf, const Observation& obs, std::int64_t t_ns) {
  const InnovationMoments stats = ekf.innovation_moments(obs);
  const double spread = stats.spread;
  InnovationWindow::Sample s;
  s.time_ns = t_ns;
  s.nis_per_dim = stats.nis / obs.rows();
  for (int i = 0; i < obs.rows(); ++i) s.residual[static_cast<std::size_t>(i)] = obs.residual(i);
  s.lambda = spread > 0.0 ? (obs.residual.squaredNorm() - obs.r.trace()) / spread : 0.0;
  return s;
}

void adapt_to_innovation(FilterCore& c, const FilterOptions& o, InnovationWindow& window,
                         const Observation& obs, std::int64_t now_ns) {
  const AdaptationOptions& a = o.adaptation;
  if (!a.enabled || obs.rows() == 0) return;
  c.flush_covariance(o);
  const InnovationWindow::Sample sample = innovation_sample(c.ekf, obs, now_ns);
  if (!std::isfinite(sample.nis_per_dim) || !std::isfinite(sample.lambda)) return;
  window.push(sample);
  const auto medians = window.recent_medians(now_ns, a.window_s, a.min_samples, a.inflate_ratio);
  if (!medians) return;

  // Process noise grows only on evidence, innovations above their predicted spread (median
  // NIS / m > 1), and then by what the covariance ratio asks (up to 4^gain per sample); it
  // shrinks when the innovations fall short (NIS / m < 1). lambda alone is no evidence: when the
  // state spread is tiny next to R it is the difference of two noisy numbers over a small one.
  // Never faster than NIS / m itself says: when P is small next to R a NIS / m of 1.2 (common
  // by chance) can come with a lambda of 50.
  const double ratio = medians->nis_per_dim > 1.0
                           ? std::clamp(medians->lambda, 1.0, medians->nis_per_dim)
                           : medians->nis_per_dim;
  const double step = std::pow(std::clamp(ratio, 0.25, 4.0), a.process_noise_gain);
  c.adaptation.process_noise_scale =
      std::clamp(c.adaptation.process_noise_scale * step, 1.0, a.max_process_noise_scale);
  c.adaptation.max_process_noise_scale =
      std::max(c.adaptation.max_process_noise_scale, c.adaptation.process_noise_scale);

  if (medians->nis_per_dim < a.inflate_ratio || medians->lambda <= 1.0 || !medians->residuals_agree) return;
  const double scale = std::sqrt(std::min(medians->lambda, a.max_inflation));
  // Position and velocity only: they are what the aid observes directly. Inflating attitude too
  // would throw away a heading that GNSS rebuilds only slowly (through accelerations), and an
  // attitude that is worse than P says is caught by the process noise scale instead. On the real
  // walk (walk_0827, data-sheet noise) inflating attitude as well tripled the error at the end of
  // 10 s outages.
  constexpr int kBlock = sx::kAtt;
  const int n = c.ekf.n;
  std::optional<Covariance> before;
  if (c.record.sink != nullptr) before = c.ekf.p;
  c.ekf.p.topRows(kBlock).leftCols(n) *= scale;
  c.ekf.p.leftCols(kBlock).topRows(n) *= scale;
  if (before) {
    // P <- D P D, D = diag(scale on position and velocity, 1): the error state mapped by D, a
    // zero-length step with transition D and no noise. As process noise instead (D P D - P, not
    // positive semi-definite when correlations are scaled) the smoother's gain amplifies: on the
    // calibration drive with a wrong mounting it smoothed the accelerometer bias to 1 m/s^2.
    SystemRows d = SystemRows::Zero();
    d.leftCols<sx::kDynamicCount>().setIdentity();
    d.topRows<kBlock>() *= scale;
    // Made while dead reckoning (update_mode's decision): the fixes that end an outage found P
    // grown too little.
    record_covariance_change(c, *before, d, c.mode.mode == NavMode::kDeadReckoning);
  }
  ++c.adaptation.inflations;
  c.adaptation.position.clear();
  c.adaptation.velocity.clear();
}

}  // namespace navfuse::filter

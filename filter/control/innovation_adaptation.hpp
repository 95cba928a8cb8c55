// Innovation-based adaptation: the filter notices when its covariance is too small for what the
// aiding shows and recovers by itself, instead of rejecting a healthy GNSS stream at the gate.
//
// Each absolute aid (GNSS position, GNSS velocity) keeps a short window of two numbers per
// update tried: the normalised innovation squared per dimension, NIS / m (1 on average for a
// consistent filter, whatever the balance of P and R), and the covariance ratio
//
//   lambda_i = (nu^T nu - tr R) / tr(H P H^T)
//
// the factor by which the predicted state spread H P H^T would have to grow for the innovation
// nu to be as large as expected (Ding, Wang, Rizos, Kinlay 2007, "Improving adaptive Kalman
// estimation in GPS/INS integration", J. Navigation 60(3), eq. 16). Medians over the window, so
// one wild fix moves neither.
//
// Two responses, both bounded:
// - Covariance re-inflation (fading memory; Xia, Rao, Ying, Shen 1994, "Adaptive fading Kalman
//   filter with an application", Automatica 30(8)): when the median NIS / m over the last
//   `window_s` is above `inflate_ratio` with at least `min_samples` samples (innovations
//   persistently 1.7x their predicted std or more), the position and velocity block of P is
//   scaled by the median lambda (correlations kept: P <- D P D), the window is cleared and the
//   measurement is then gated against the honest covariance. A single outlier never triggers it,
//   nor a cluster of glitches: the recent residuals must also agree with each other (their mean
//   larger than their scatter), as they do when the filter has drifted off a healthy stream.
// - Process noise scaling (Ding et al. 2007 §3): the velocity and attitude random walks are
//   multiplied by `process_noise_scale`: up by the median lambda when the median NIS / m says
//   the innovations exceed their predicted spread, down when they fall short, never below 1 (the
//   data sheet is the floor: vibration only adds noise) nor above `max_process_noise_scale`.
//   Under a consistent filter the median NIS / m sits below 1 (0.79 for 3 dimensions), so the
//   scale stays at the floor.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "filter/control/measurement_noise_adaptation.hpp"
#include "filter/ekf.hpp"
#include "filter/filter_options.hpp"

namespace navfuse::filter {

struct FilterCore;

// The newest samples of one aid, with their times (fixed size: FilterCore holds no heap).
struct InnovationWindow {
  static constexpr int kCapacity = 16;
  struct Sample {
    std::int64_t time_ns = 0;
    double nis_per_dim = 0.0;
    double lambda = 0.0;
    std::array<double, 3> residual{};  // zero-padded beyond the measurement's rows
  };
  std::array<Sample, kCapacity> samples{};
  int count = 0;
  int next = 0;

  void push(const Sample& s);
  void clear() { count = next = 0; }
  // Medians of the samples not older than `window_s` before `now_ns`; nullopt when fewer than
  // `min_samples` are that recent.
  struct Medians {
    double nis_per_dim = 0.0;
    double lambda = 0.0;
    // The recent large residuals (NIS / m >= large_nis) agree: their mean is larger than their
    // scatter about it. A filter that drifted off a healthy stream sees one offset; GNSS
    // glitches point anywhere.
    bool residuals_agree = false;
  };
  std::optional<Medians> recent_medians(std::int64_t now_ns, double window_s, int min_samples,
                                        double large_nis = 1.0) const;
};

struct AdaptationState {
  InnovationWindow position;
  InnovationWindow velocity;
  NoiseScaleWindow position_noise;  // GNSS position R multiplier
  NoiseScaleWindow velocity_noise;  // GNSS velocity R multiplier
  double process_noise_scale = 1.0;
  double max_process_noise_scale = 1.0;  // largest reached, for the summary
  std::uint64_t inflations = 0;
};

// NIS / m and lambda for one observation against the current covariance (before its update).
InnovationWindow::Sample innovation_sample(const Ekf& ekf, const Observation& obs, std::int64_t t_ns);

// Records the observation's lambda in `window` and, when the recent ones say the filter is
// overconfident, re-inflates P and raises the process noise scale. Call before the update.
void adapt_to_innovation(FilterCore& core, const FilterOptions& o, InnovationWindow& window,
                         const Observation& obs, std::int64_t now_ns);

}  // namespace navfuse::filter

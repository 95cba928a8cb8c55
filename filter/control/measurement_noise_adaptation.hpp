// Measurement-noise adaptation: the filter notices when an aid's reported std devs are smaller
// than its real errors and scales its R up, instead of rejecting a healthy stream at the gate.
//
// Receivers' own figures are often optimistic: RTKLIB reports a few millimetres (sdn/sde/sdu) for
// fixed solutions whose errors on a moving car are 1-3 cm. With R that small every fix is sharper
// than the data can support; the innovations exceed the gate whenever the INS has drifted by the
// real error, and re-inflating P (innovation_adaptation.hpp) only makes the filter follow the
// noise. On parking_drive with the fixes' std reported 4x too small, 47 % of the fixes were
// rejected. That is the failure issue 14 describes on the held-out drive.
//
// The estimate is innovation-based adaptive estimation of R (Mohamed & Schwarz 1999, "Adaptive
// Kalman filtering for INS/GPS", J. Geodesy 73(4), eq. 21: R = C_v - H P H^T with C_v the
// innovation covariance over a window), reduced to one variance multiplier per aid so that the
// receiver's own weighting of axes and epochs is kept:
//
//   rho_k = (nu^T nu - tr(H P H^T)) / tr(R_k)
//
// for every update tried (accepted or gated: a window of accepted ones only would never see the
// large ones). Over the window the median is robust to a few outliers and to the large residuals
// of a filter that drifted (which innovation_adaptation.hpp repairs in P); it is divided by the
// median of chi-square(m) / m (the median of nu^T nu / E[nu^T nu] for an m-dimensional residual)
// to estimate the mean. The multiplier is that estimate, floored at 1 (never trust a receiver more
// than it claims: its std devs also carry its own knowledge of bad epochs) and capped at
// adaptation.max_measurement_noise_scale. It applies only while the reported R would gate out at
// least 5 % of the window: R is left as reported as long as the gate passes what arrives, since
// a larger R also weakens what the fixes teach the filter before an outage (on the shared walk,
// always adapting moved the 10 s outage ends from 1.6 to 3.1 m).
#pragma once

#include <array>
#include <cstdint>

#include "filter/ekf.hpp"
#include "filter/filter_options.hpp"

namespace navfuse::filter {

// The recent rho samples of one aid and the variance multiplier they give.
struct NoiseScaleWindow {
  static constexpr int kCapacity = 32;
  // Fewer samples than this say nothing: the multiplier stays where it is.
  static constexpr int kMinSamples = 8;
  std::array<double, kCapacity> rho{};
  std::array<std::array<double, 3>, kCapacity> residual{};  // zero-padded beyond the rows
  std::array<bool, kCapacity> gated{};  // outside the gate with R as reported
  int count = 0;
  int next = 0;
  double scale = 1.0;      // multiplier on R's variances
  double max_scale = 1.0;  // largest reached, for the summary
};

// Records the sample of `obs` (R as reported and configured, before the multiplier), updates the
// window's multiplier and returns it. Call before the update, with the covariance it will use;
// `gate`: the chi-square gate the update will be held to.
double update_noise_scale(NoiseScaleWindow& w, const Ekf& ekf, const Observation& obs, const AdaptationOptions& a,
                          double gate);

}  // namespace navfuse::filter

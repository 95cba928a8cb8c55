// The IMU biases over a log as the calibration estimates them: constant within segments of equal
// length, each segment's change from the one before weighted as the random walk the configured
// bias instability drifts like. One constant over an hour-long log would leave a drifting bias's
// mismatch in the IMU factors, where the fit takes it out of whatever it can move (lever arm,
// mounting, time offset); a bias block per epoch (as sliding-window VIO does) is the exact
// random walk but six more unknowns every half second. Segments keep the unknowns few while the
// preintegration's own drift allowance (ImuPreintegration::add_bias_drift) covers the change
// inside an interval.
//
// Between neighbouring segments (centres `length_s` apart) the change's std dev is
// density * sqrt(length_s): the random walk a first-order Gauss-Markov bias follows over spans
// short against its correlation time (q = sqrt(2 sigma^2 / tau); calibration_collector.cpp). For
// a span that is not short the exact variance 2 sigma^2 (1 - exp(-T / tau)) is smaller: the
// allowance errs wide (0.4 sigma^2 against 0.36 at T = 60 s, tau = 300 s).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "calibration/calibration_result.hpp"

namespace ceres {
class Covariance;
class Problem;
}  // namespace ceres

namespace navfuse::calib {

// Shorter is always nearer the true random walk (the step factors tie neighbours as tightly as the
// configured drift says, so a slowly drifting IMU's segments stay nearly one bias); the cost is six
// unknowns per segment and, in ceres::Covariance, six columns each. On a drive whose biases wander
// by their own size within a minute (tests/calibration/calibration_problem_test.cpp
// DriftingBiases...) 60 s segments left a lever arm 5 cm off at 11 std devs, 10 s none.
struct BiasSegmentOptions {
  double length_s = 10.0;       // <= 0: one bias over the whole log
  std::size_t max_count = 120;  // a longer log gets longer segments (30 s for an hour)
};

class BiasSegments {
 public:
  // Segments of equal length over [first_ns, last_ns]; one when a configured drift density is zero
  // (nothing says how far neighbours may differ) or the span is shorter than a segment.
  BiasSegments(std::int64_t first_ns, std::int64_t last_ns, const BiasSegmentOptions& options, double gyro_density_rps_rts,
               double accel_density_mps2_rts, const Eigen::Vector3d& bg0, const Eigen::Vector3d& ba0)
      : first_ns_(first_ns) {
    const double span_s = static_cast<double>(std::max<std::int64_t>(0, last_ns - first_ns)) * 1e-9;
    std::size_t n = 1;
    if (options.length_s > 0.0 && gyro_density_rps_rts > 0.0 && accel_density_mps2_rts > 0.0) {
      n = static_cast<std::size_t>(std::clamp(std::round(span_s / options.length_s), 1.0,
                                              static_cast<double>(std::max<std::size_t>(1, options.max_count))));
    }
    length_ns_ = n > 1 ? static_cast<double>(last_ns - first_ns) / static_cast<double>(n) : 0.0;
    gyro_step_std_ = gyro_density_rps_rts * std::sqrt(length_ns_ * 1e-9);
    accel_step_std_ = accel_density_mps2_rts * std::sqrt(length_ns_ * 1e-9);
    bg_.assign(n, {bg0.x(), bg0.y(), bg0.z()});
    ba_.assign(n, {ba0.x(), ba0.y(), ba0.z()});
  }

  std::size_t count() const { return bg_.size(); }
  // The segment a stamp falls in (stamps outside the span go to the nearest end).
  std::size_t at(std::int64_t time_ns) const {
    if (count() == 1) return 0;
    const double k = std::floor(static_cast<double>(time_ns - first_ns_) / length_ns_);
    return static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(count() - 1)));
  }
  std::int64_t start_ns(std::size_t k) const {
    return first_ns_ + static_cast<std::int64_t>(std::llround(length_ns_ * static_cast<double>(k)));
  }
  double length_s() const { return length_ns_ * 1e-9; }
  // The std devs of a neighbour's change (zero with one segment).
  double gyro_step_std_rps() const { return gyro_step_std_; }
  double accel_step_std_mps2() const { return accel_step_std_; }

  // Parameter blocks (sensor frame), stable addresses once constructed.
  double* gyro(std::size_t k) { return bg_[k].data(); }
  double* accel(std::size_t k) { return ba_[k].data(); }
  const double* gyro(std::size_t k) const { return bg_[k].data(); }
  const double* accel(std::size_t k) const { return ba_[k].data(); }

 private:
  std::int64_t first_ns_;
  double length_ns_ = 0.0;
  double gyro_step_std_ = 0.0, accel_step_std_ = 0.0;
  std::vector<std::array<double, 3>> bg_, ba_;
};

// r = (b_next - b) / std: one segment's bias to the next (Ceres residual, 3 x [3, 3]).
class BiasStepFactor {
 public:
  explicit BiasStepFactor(double step_std) : inv_std_(1.0 / step_std) {}
  template <typename T>
  bool operator()(const T* b, const T* b_next, T* r) const {
    for (int i = 0; i < 3; ++i) r[i] = (b_next[i] - b[i]) * T(inv_std_);
    return true;
  }

 private:
  double inv_std_;
};

// The step factors between neighbouring segments (none with one segment).
void add_bias_steps(ceres::Problem& problem, BiasSegments& biases);
// What ceres::Covariance needs for bias_estimates(): every segment's blocks with every other's
// (the mean's std dev takes their correlations).
void add_bias_covariance_pairs(const BiasSegments& biases, std::vector<std::pair<const double*, const double*>>& pairs);
// Fills result.bias_segments and the means over them; std devs (times `std_scale`, the fit's
// variance factor's root) from `covariance` when given. False when a block was not computable.
bool bias_estimates(ceres::Covariance* covariance, const BiasSegments& biases, double std_scale, CalibrationResult& result);

}  // namespace navfuse::calib

#include "calibration/bias_segments.hpp"

#include <ceres/ceres.h>

namespace navfuse::calib {

void add_bias_steps(ceres::Problem& problem, BiasSegments& biases) {
  for (std::size_t k = 1; k < biases.count(); ++k) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<BiasStepFactor, 3, 3, 3>(
                                 new BiasStepFactor(biases.gyro_step_std_rps())),
                             nullptr, biases.gyro(k - 1), biases.gyro(k));
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<BiasStepFactor, 3, 3, 3>(
                                 new BiasStepFactor(biases.accel_step_std_mps2())),
                             nullptr, biases.accel(k - 1), biases.accel(k));
  }
}

void add_bias_covariance_pairs(const BiasSegments& biases, std::vector<std::pair<const double*, const double*>>& pairs) {
  for (std::size_t k = 0; k < biases.count(); ++k) {
    for (std::size_t l = k; l < biases.count(); ++l) {
      pairs.emplace_back(biases.gyro(k), biases.gyro(l));
      pairs.emplace_back(biases.accel(k), biases.accel(l));
    }
  }
}

namespace {

// The mean of one kind of bias over the segments and each segment's value, with std devs:
// var(mean) = sum_kl C_kl / N^2.
bool fill(ceres::Covariance* covariance, const std::vector<const double*>& blocks, double std_scale, Estimate3& mean,
          std::vector<Estimate3>& per_segment) {
  const std::size_t n = blocks.size();
  per_segment.assign(n, {});
  mean = {};
  for (std::size_t k = 0; k < n; ++k) {
    per_segment[k].value = Eigen::Map<const Eigen::Vector3d>(blocks[k]);
    mean.value += per_segment[k].value / static_cast<double>(n);
  }
  if (covariance == nullptr) return false;
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> c;
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t l = k; l < n; ++l) {
      if (!covariance->GetCovarianceBlock(blocks[k], blocks[l], c.data())) return false;
      if (k == l) {
        per_segment[k].std = std_scale * c.diagonal().cwiseMax(0.0).cwiseSqrt();
        sum += c;
      } else {
        sum += c + c.transpose();
      }
    }
  }
  mean.std = std_scale * (sum.diagonal() / static_cast<double>(n * n)).cwiseMax(0.0).cwiseSqrt();
  return true;
}

}  // namespace

bool bias_estimates(ceres::Covariance* covariance, const BiasSegments& biases, double std_scale, CalibrationResult& result) {
  const std::size_t n = biases.count();
  std::vector<const double*> gyro_blocks(n), accel_blocks(n);
  for (std::size_t k = 0; k < n; ++k) {
    gyro_blocks[k] = biases.gyro(k);
    accel_blocks[k] = biases.accel(k);
  }
  std::vector<Estimate3> gyro, accel;
  const bool gyro_ok = fill(covariance, gyro_blocks, std_scale, result.gyro_bias_rps, gyro);
  const bool accel_ok = fill(covariance, accel_blocks, std_scale, result.accel_bias_mps2, accel);
  result.bias_segments.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    result.bias_segments[k] = {.start_ns = biases.start_ns(k), .gyro_bias_rps = gyro[k], .accel_bias_mps2 = accel[k]};
  }
  return gyro_ok && accel_ok;
}

}  // namespace navfuse::calib

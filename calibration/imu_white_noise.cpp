// IMU white noise from the samples' second differences (see imu_white_noise.hpp for the method).
#include "calibration/imu_white_noise.hpp"

#include <algorithm>
#include <cmath>

#include "calibration/calibration_epochs.hpp"
#include "calibration/median.hpp"

namespace navfuse::calib {
namespace {

// Median of chi-square with one degree of freedom: median(d^2) = kChi2Median1 var(d) for normal d.
constexpr double kChi2Median1 = 0.454936423119572;
// var(x_{k+1} - 2 x_k + x_{k-1}) = (1 + 4 + 1) sigma^2 for white x.
constexpr double kSecondDifferenceGain = 6.0;

}  // namespace

ImuWhiteNoise measure_white_noise(const std::vector<ImuSample>& imu, std::size_t first, std::size_t last,
                                  double block_s) {
  ImuWhiteNoise out;
  if (imu.empty() || last >= imu.size() || last < first + 2) return out;
  // Running sums of the increments (rates times their dt) from `first`; a non-finite or
  // interval-less sample ends nothing, it only marks the blocks that hold it as unusable.
  const std::size_t n = last - first + 1;
  std::vector<Eigen::Vector3d> gyro_sum(n + 1, Eigen::Vector3d::Zero()), accel_sum(n + 1, Eigen::Vector3d::Zero());
  std::vector<std::size_t> bad_sum(n + 1, 0);
  double dt_sum = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const ImuRates r = imu_rates(imu, first + k);
    const bool ok = r.dt_s > 0.0 && r.gyro_rps.allFinite() && r.accel_mps2.allFinite();
    gyro_sum[k + 1] = gyro_sum[k] + (ok ? Eigen::Vector3d(r.gyro_rps * r.dt_s) : Eigen::Vector3d::Zero());
    accel_sum[k + 1] = accel_sum[k] + (ok ? Eigen::Vector3d(r.accel_mps2 * r.dt_s) : Eigen::Vector3d::Zero());
    bad_sum[k + 1] = bad_sum[k] + (ok ? 0 : 1);
    if (ok) dt_sum += r.dt_s;
  }
  const std::size_t good = n - bad_sum[n];
  if (good == 0) return out;
  const double dt = dt_sum / static_cast<double>(good);
  const auto m = static_cast<std::size_t>(std::max(1.0, std::round(block_s / dt)));
  // D_k = S(k + m) - 2 S(k) + S(k - m) with S(k) the sum of samples k .. k + m - 1: samples
  // k - m .. k + 2m - 1, weights 1, -2, 1 per block.
  std::vector<double> gyro_d2, accel_d2;
  std::size_t count = 0;
  for (std::size_t k = m; k + 2 * m <= n; ++k) {
    if (bad_sum[k + 2 * m] != bad_sum[k - m]) continue;
    const auto block = [&](const std::vector<Eigen::Vector3d>& sum, std::size_t from) -> Eigen::Vector3d {
      return sum[from + m] - sum[from];
    };
    const Eigen::Vector3d dg = block(gyro_sum, k + m) - 2.0 * block(gyro_sum, k) + block(gyro_sum, k - m);
    const Eigen::Vector3d da = block(accel_sum, k + m) - 2.0 * block(accel_sum, k) + block(accel_sum, k - m);
    for (int a = 0; a < 3; ++a) {
      gyro_d2.push_back(dg[a] * dg[a]);
      accel_d2.push_back(da[a] * da[a]);
    }
    ++count;
  }
  if (count < kMinWhiteNoiseSamples) return out;
  // var(D) = 6 m N^2 dt for white increments of variance N^2 dt.
  const double to_density2 = 1.0 / (kChi2Median1 * kSecondDifferenceGain * static_cast<double>(m) * dt);
  out.gyro_rad_rts = std::sqrt(median_in_place(gyro_d2) * to_density2);
  out.accel_mps_rts = std::sqrt(median_in_place(accel_d2) * to_density2);
  out.samples = count;
  return out;
}

ImuWhiteNoise least_white_noise(const ImuWhiteNoise& a, const ImuWhiteNoise& b) {
  if (a.samples == 0) return b;
  if (b.samples == 0) return a;
  return {.gyro_rad_rts = std::min(a.gyro_rad_rts, b.gyro_rad_rts),
          .accel_mps_rts = std::min(a.accel_mps_rts, b.accel_mps_rts),
          .samples = std::min(a.samples, b.samples)};
}

}  // namespace navfuse::calib

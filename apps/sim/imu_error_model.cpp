// IMU error generation (see imu_error_model.hpp for the model and its sources).
#include "apps/sim/imu_error_model.hpp"

#include <cmath>

#include "core/geodesy/wgs84.hpp"
#include "core/measurements/measurements.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

// Datasheet units -> SI. deg/sqrt(h) -> rad/sqrt(s): 1 sqrt(h) = 60 sqrt(s).
constexpr double kDegPerRootHourToRadPerRootSec = rot::kDegToRad / 60.0;
constexpr double kMpsPerRootHourToMpsPerRootSec = 1.0 / 60.0;
constexpr double kDegPerHourToRadPerSec = rot::kDegToRad / 3600.0;
constexpr double kMilliG = 1e-3 * geo::wgs84::kStandardGravity_mps2;

Eigen::Vector3d normal3(Rng& rng, double std) {
  // Draw even when std == 0 so that the random stream does not depend on which terms are on.
  const Eigen::Vector3d w(rng.normal(), rng.normal(), rng.normal());
  return std * w;
}

// Clips each axis to +-limit (limit > 0) and returns the bits (first_bit << axis) of clipped axes.
std::uint8_t saturate(Eigen::Vector3d& v, double limit, std::uint8_t first_bit) {
  std::uint8_t bits = 0;
  if (!(limit > 0.0)) return bits;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(v[i]) > limit) {
      v[i] = std::copysign(limit, v[i]);
      bits |= static_cast<std::uint8_t>(first_bit << i);
    }
  }
  return bits;
}

}  // namespace

ImuErrorSpec imu_error_spec(ImuGrade grade) {
  ImuErrorSpec s;
  switch (grade) {
    case ImuGrade::kPerfect:
      break;
    case ImuGrade::kTactical:
      s.gyro_arw_deg_rthr = 0.02;
      s.gyro_bias_instability_deg_hr = 0.5;
      s.gyro_turn_on_bias_std_deg_hr = 3.0;
      s.gyro_scale_factor_std_ppm = 100.0;
      s.accel_vrw_mps_rthr = 0.02;
      s.accel_bias_instability_mps2 = 0.05 * kMilliG;
      s.accel_turn_on_bias_std_mps2 = 1.0 * kMilliG;
      s.accel_scale_factor_std_ppm = 100.0;
      break;
    case ImuGrade::kIndustrial:
      s.gyro_arw_deg_rthr = 0.1;
      s.gyro_bias_instability_deg_hr = 2.0;
      s.gyro_turn_on_bias_std_deg_hr = 20.0;
      s.gyro_scale_factor_std_ppm = 300.0;
      s.accel_vrw_mps_rthr = 0.03;
      s.accel_bias_instability_mps2 = 0.02 * kMilliG;
      s.accel_turn_on_bias_std_mps2 = 5.0 * kMilliG;
      s.accel_scale_factor_std_ppm = 300.0;
      break;
    case ImuGrade::kConsumer:
      s.gyro_arw_deg_rthr = 0.3;
      s.gyro_bias_instability_deg_hr = 10.0;
      s.gyro_turn_on_bias_std_deg_hr = 1800.0;  // 0.5 deg/s
      s.gyro_scale_factor_std_ppm = 5000.0;
      s.gyro_range_dps = 250.0;
      s.accel_vrw_mps_rthr = 0.1;
      s.accel_bias_instability_mps2 = 0.1 * kMilliG;
      s.accel_turn_on_bias_std_mps2 = 30.0 * kMilliG;
      s.accel_scale_factor_std_ppm = 5000.0;
      s.accel_range_mps2 = 8.0 * geo::wgs84::kStandardGravity_mps2;
      break;
  }
  return s;
}

ImuErrorModel::ImuErrorModel(const ImuErrorSpec& spec, std::uint64_t seed)
    : spec_(spec), rng_(seed, RandomStream::kImu) {
  // Per-seed constants first, in a fixed order.
  gyro_turn_on_rps_ = normal3(rng_, spec_.gyro_turn_on_bias_std_deg_hr * kDegPerHourToRadPerSec);
  accel_turn_on_mps2_ = normal3(rng_, spec_.accel_turn_on_bias_std_mps2);
  gyro_scale_ = normal3(rng_, spec_.gyro_scale_factor_std_ppm * 1e-6);
  accel_scale_ = normal3(rng_, spec_.accel_scale_factor_std_ppm * 1e-6);
  // The Gauss-Markov processes start in their stationary distribution, so their variance does not
  // depend on how long the run has been going.
  gyro_gm_rps_ = normal3(rng_, spec_.gyro_bias_instability_deg_hr * kDegPerHourToRadPerSec);
  accel_gm_mps2_ = normal3(rng_, spec_.accel_bias_instability_mps2);
}

std::uint8_t ImuErrorModel::apply(bool increments, double dt_s, Eigen::Vector3d& gyro,
                                  Eigen::Vector3d& accel) {
  const double gyro_noise = spec_.gyro_arw_deg_rthr * kDegPerRootHourToRadPerRootSec;
  const double accel_noise = spec_.accel_vrw_mps_rthr * kMpsPerRootHourToMpsPerRootSec;
  // White rate noise of PSD N^2: its integral over dt has std N sqrt(dt), its mean over dt has
  // std N / sqrt(dt) (IEEE Std 952 Annex C.1).
  const double noise_scale = increments ? std::sqrt(dt_s) : 1.0 / std::sqrt(dt_s);
  const double bias_scale = increments ? dt_s : 1.0;

  const Eigen::Vector3d gyro_bias = gyro_bias_rps();
  const Eigen::Vector3d accel_bias = accel_bias_mps2();
  gyro = gyro + gyro_scale_.cwiseProduct(gyro) + bias_scale * gyro_bias +
         normal3(rng_, gyro_noise * noise_scale);
  accel = accel + accel_scale_.cwiseProduct(accel) + bias_scale * accel_bias +
          normal3(rng_, accel_noise * noise_scale);

  // Exact discretisation of the first-order Gauss-Markov bias db/dt = -b / tau + w:
  // phi = e^(-dt/tau), and b_k = phi b_(k-1) + sqrt(1 - phi^2) sigma w_k keeps the variance at
  // sigma^2 for any dt.
  auto advance = [&](Eigen::Vector3d& b, double sigma, double tau_s) {
    const double phi = tau_s > 0.0 ? std::exp(-dt_s / tau_s) : 0.0;
    b = phi * b + normal3(rng_, sigma * std::sqrt(1.0 - phi * phi));
  };
  advance(gyro_gm_rps_, spec_.gyro_bias_instability_deg_hr * kDegPerHourToRadPerSec,
          spec_.gyro_bias_corr_time_s);
  advance(accel_gm_mps2_, spec_.accel_bias_instability_mps2, spec_.accel_bias_corr_time_s);

  const double range_scale = increments ? dt_s : 1.0;
  std::uint8_t bits = saturate(gyro, spec_.gyro_range_dps * rot::kDegToRad * range_scale,
                               ImuSample::kSatGyroX);
  bits |= saturate(accel, spec_.accel_range_mps2 * range_scale, ImuSample::kSatAccelX);
  return bits;
}

}  // namespace navfuse::sim

// IMU sensor errors: what turns the true increments of a perfect IMU into a real sensor's output.
//
// Per axis, in the sensor frame (IEEE Std 952-1997 Annex C terminology; Groves §4.4 error
// characteristics):
//   output = (1 + scale_factor) * truth + bias * dt + noise          (increments)
//   output = (1 + scale_factor) * truth + bias      + noise          (rates)
//   bias   = turn_on_bias + b_gm
// - Angle / velocity random walk (ARW, VRW): white rate noise of PSD N^2. Over an increment of
//   length dt its integral has std N * sqrt(dt); a rate sample averaged over dt has std
//   N / sqrt(dt) (IEEE 952 C.1).
// - Bias instability: modelled as a first-order Gauss-Markov process b_gm with stationary std
//   equal to the bias instability figure and the given correlation time. (IEEE 952 C.2 defines
//   bias instability as the flat floor of the Allan deviation, which for flicker noise is ~0.664
//   of its sigma; a GM process is the usual finite-state stand-in and what the filter models.)
//   Discretised exactly:
//   b_k = e^(-dt/tau) b_(k-1) + sqrt(1 - e^(-2 dt/tau)) * sigma * w_k.
// - Turn-on bias: a random constant per seed (N(0, std^2) per axis), the run-to-run bias.
// - Scale factor: a random constant per seed and axis, N(0, (ppm * 1e-6)^2).
// - Saturation: outputs beyond the range are clipped and flagged (ImuSample::kSat* bits).
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "apps/sim/random.hpp"

namespace navfuse::sim {

// Error parameters, in the units datasheets use (as in the `imu:` config keys). Zero disables a
// term.
struct ImuErrorSpec {
  double gyro_arw_deg_rthr = 0.0;               // angle random walk, deg/sqrt(h)
  double gyro_bias_instability_deg_hr = 0.0;    // Gauss-Markov stationary std, deg/h
  double gyro_bias_corr_time_s = 300.0;         // Gauss-Markov correlation time
  double gyro_turn_on_bias_std_deg_hr = 0.0;    // run-to-run constant bias std, deg/h
  double gyro_scale_factor_std_ppm = 0.0;
  double gyro_range_dps = 0.0;                  // saturation limit, deg/s (0: none)

  double accel_vrw_mps_rthr = 0.0;              // velocity random walk, m/s/sqrt(h)
  double accel_bias_instability_mps2 = 0.0;     // Gauss-Markov stationary std
  double accel_bias_corr_time_s = 300.0;
  double accel_turn_on_bias_std_mps2 = 0.0;     // run-to-run constant bias std
  double accel_scale_factor_std_ppm = 0.0;
  double accel_range_mps2 = 0.0;                // saturation limit (0: none)
};

// Named grades with typical datasheet figures.
enum class ImuGrade : std::uint8_t {
  kPerfect = 0,     // no errors at all (truth increments)
  kTactical = 1,    // FOG-class: ARW 0.02 deg/rt-h, BI 0.5 deg/h
  kIndustrial = 2,  // the filter tests' reference grade: ARW 0.1 deg/rt-h, BI 2 deg/h, turn-on
                    // 20 deg/h, accel bias 5 mg, VRW 0.03 m/s/rt-h
  kConsumer = 3,    // automotive MEMS: ARW 0.3 deg/rt-h, BI 10 deg/h, turn-on 0.5 deg/s
};
ImuErrorSpec imu_error_spec(ImuGrade grade);

// Stateful error generator for one IMU (gyro and accelerometer triads), deterministic for a seed.
class ImuErrorModel {
 public:
  ImuErrorModel(const ImuErrorSpec& spec, std::uint64_t seed);

  // Applies the errors to one sample of true sensor-frame values and advances the bias process by
  // `dt_s`. `increments` selects the noise scaling (see file comment). Returns the saturation
  // bits (ImuSample::kSat*).
  std::uint8_t apply(bool increments, double dt_s, Eigen::Vector3d& gyro, Eigen::Vector3d& accel);

  // Current total biases in the sensor frame (rad/s, m/s^2) and the per-seed scale factors.
  Eigen::Vector3d gyro_bias_rps() const { return gyro_turn_on_rps_ + gyro_gm_rps_; }
  Eigen::Vector3d accel_bias_mps2() const { return accel_turn_on_mps2_ + accel_gm_mps2_; }
  const Eigen::Vector3d& gyro_scale_factor() const { return gyro_scale_; }
  const Eigen::Vector3d& accel_scale_factor() const { return accel_scale_; }

 private:
  ImuErrorSpec spec_;
  Rng rng_;
  Eigen::Vector3d gyro_turn_on_rps_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_turn_on_mps2_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_gm_rps_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_gm_mps2_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_scale_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_scale_ = Eigen::Vector3d::Zero();
};

}  // namespace navfuse::sim

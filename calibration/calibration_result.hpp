// What the calibration found: each installation parameter with its std dev (from the solver's
// covariance, ceres::Covariance), and how the solve went.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace navfuse::calib {

struct Estimate3 {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  Eigen::Vector3d std = Eigen::Vector3d::Zero();  // 0: not estimated (held at the configured value)
};
struct Estimate2 {
  Eigen::Vector2d value = Eigen::Vector2d::Zero();
  Eigen::Vector2d std = Eigen::Vector2d::Zero();
};
struct Estimate1 {
  double value = 0.0;
  double std = 0.0;
};

struct CalibrationResult {
  Estimate3 gnss_lever_arm_m;    // vehicle frame
  // Where the vehicle does not slip (vehicle frame): estimated when the config only guessed it
  // (nhc.lever_arm_std_m above 0), else the configured point, std 0.
  Estimate3 nhc_lever_arm_m;
  bool nhc_lever_arm_estimated = false;
  // The mounting as the config key gives it (sensor -> vehicle, roll, pitch, yaw): the configured
  // one turned by the residual vehicle pitch and yaw below (mounting_dcm); the vehicle frame's
  // roll is held. The Euler angles' stds follow from the residual's covariance.
  Estimate3 mounting_rpy_rad;
  Estimate2 mounting_residual_rad;  // vehicle pitch, yaw about the configured mounting
  bool mounting_estimated = false;  // false: no odometry, NHC or heading saw it
  // The IMU reported in the vehicle frame (the device's own mounting): the mounting is then a
  // residual about the vehicle axes, not the config key's sensor -> vehicle rotation.
  bool mounting_is_residual = false;
  Estimate1 imu_time_offset_s;   // the config key's meaning: added to IMU stamps
  std::optional<Estimate1> odometer_scale;  // measured / true speed; none without wheel speeds
  // Sensor frame: the mean over the log of the biases in `bias_segments` (bias_segments.hpp), its
  // std dev with their correlations.
  Estimate3 gyro_bias_rps;
  Estimate3 accel_bias_mps2;
  struct BiasSegment {
    std::int64_t start_ns = 0;  // IMU clock
    Estimate3 gyro_bias_rps, accel_bias_mps2;
  };
  std::vector<BiasSegment> bias_segments;  // time order; one when the biases are held constant
  Estimate3 gyro_scale;   // fractional scale-factor errors, sensor frame (measured = (1 + s) true)
  Estimate3 accel_scale;

  // The solve.
  std::uint64_t epochs = 0;           // states
  std::uint64_t imu_factors = 0;
  std::uint64_t gnss_position_residuals = 0;
  std::uint64_t gnss_velocity_residuals = 0;
  std::uint64_t gnss_heading_residuals = 0;
  std::uint64_t external_residuals = 0;  // external aiding: positions, velocities, headings
  std::uint64_t speed_residuals = 0;
  std::uint64_t nhc_residuals = 0;
  int iterations = 0;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  double position_rms_m = 0.0;  // GNSS position residual RMS after the fit (antenna, metres)
  // Mean squared whitened IMU-factor residual per dimension of this solve (about 1 when the
  // IMU's noise is what the preintegration assumed), and the variance multiplier it was solved with.
  double imu_variance_factor = 1.0;
  double imu_noise_scale = 1.0;
  // The IMU's white noise measured from its samples (imu_white_noise.hpp), median over the IMU
  // factors; each factor used the larger of its own measurement and the data sheet's (0: not
  // measured).
  double measured_gyro_noise_rad_rts = 0.0;
  double measured_accel_noise_mps_rts = 0.0;
  double wall_s = 0.0;
  bool converged = false;
  bool covariance_ok = false;
  std::string message;  // solver's report, or why nothing was solved
};

}  // namespace navfuse::calib

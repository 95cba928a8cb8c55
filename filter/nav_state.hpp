// The nominal (total) navigation state the strapdown integrates and the EKF corrects.
#pragma once

#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "filter/state_layout.hpp"

namespace navfuse::filter {

struct NavState {
  std::int64_t time_ns = 0;
  double lat_rad = 0.0;
  double lon_rad = 0.0;
  double height_m = 0.0;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_nb = Eigen::Quaterniond::Identity();  // vehicle (FRD) -> NED
  // IMU error model, vehicle frame: measured = (1 + scale) * true + bias (+ noise).
  Eigen::Vector3d gyro_bias_rps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_scale = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_scale = Eigen::Vector3d::Zero();
  // Odometer: measured speed = (1 + wheel_scale) * true speed.
  double wheel_scale = 0.0;
  // Residual rotation of the vehicle (odometry) frame relative to the IMU-derived vehicle frame.
  double mount_pitch_rad = 0.0;
  double mount_yaw_rad = 0.0;
  Eigen::Vector3d gnss_lever_arm_m = Eigen::Vector3d::Zero();
  // A fix stamped t (GNSS time after gnss.time_offset_s) is the antenna at IMU time t + this.
  double gnss_time_offset_s = 0.0;
};

// Applies an error-state estimate (estimate minus truth) to the nominal state: x <- x - dx.
// Position errors are NED metres, converted with the radii of curvature (Groves eq. 2.111).
void inject_error(NavState& x, const StateVector& dx);

// The error of `estimate` relative to `truth` in the same convention, so that
// inject_error(estimate, state_difference(estimate, truth)) gives `truth` (to rounding): NED
// metres at the estimate's position, phi with C_truth = exp([phi x]) C_estimate. Exact for any
// size of difference (not only small ones); used to linearise the strapdown numerically.
StateVector state_difference(const NavState& estimate, const NavState& truth);

}  // namespace navfuse::filter

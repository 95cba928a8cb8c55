// What the calibration (calibration_problem.hpp) is given: the raw measurements of a log as the
// filter was offered them, the smoothed trajectory to start from, and the installation as
// configured. Plain data, no solver: navfuse_apps fills it (apps/replay/calibration_collector.hpp)
// without linking Ceres.
//
// Times: IMU samples keep their own stamps (the IMU clock, before imu.time_offset_s); GNSS and
// wheel measurements are on the GNSS time base (their configured offsets already added); the
// smoothed states are on the IMU clock too (the caller takes the configured imu.time_offset_s
// back off). The calibration estimates the IMU clock's offset, so everything else stays fixed.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/measurements/measurements.hpp"

namespace navfuse::calib {

// One smoothed state (filter/smoother/rts_smoother.hpp), vehicle frame.
struct TrajectoryPoint {
  std::int64_t time_ns = 0;  // IMU clock
  double lat_rad = 0.0, lon_rad = 0.0, height_m = 0.0;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_nv = Eigen::Quaterniond::Identity();  // vehicle (FRD) -> NED
  Eigen::Vector3d gyro_bias_v_rps = Eigen::Vector3d::Zero();     // vehicle frame
  Eigen::Vector3d accel_bias_v_mps2 = Eigen::Vector3d::Zero();
};

// A speed along the vehicle x axis at the wheel lever arm (VehicleSpeed, or the mean of the rear
// wheels of WheelSpeeds), signed (negative reversing).
struct SpeedSample {
  std::int64_t time_ns = 0;  // GNSS time base
  double speed_mps = 0.0;
  double std_mps = 0.05;
};

// The installation as configured: the starting values, and what is held fixed.
struct CalibrationSetup {
  Eigen::Vector3d gnss_lever_arm_m = Eigen::Vector3d::Zero();   // vehicle frame
  Eigen::Vector3d mounting_rpy_rad = Eigen::Vector3d::Zero();   // sensor -> vehicle, 3-2-1
  bool imu_in_vehicle_frame = false;  // the device applied its own mounting (SensorFrame::kVehicle)
  double imu_time_offset_s = 0.0;     // configured
  Eigen::Vector3d wheel_lever_arm_m = Eigen::Vector3d::Zero();
  // Primary -> secondary antenna, vehicle frame (filter/measurements/gnss_heading.hpp
  // heading_baseline_b): the vehicle's x axis for a device that reports its heading.
  Eigen::Vector3d heading_baseline_v_m = Eigen::Vector3d::UnitX();
  Eigen::Vector3d nhc_lever_arm_m = Eigen::Vector3d::Zero();
  // How well that point is known (nhc.lever_arm_std_m); above 0 on an axis, the calibration
  // estimates it there.
  Eigen::Vector3d nhc_lever_arm_std_m = Eigen::Vector3d::Zero();
  bool land_vehicle = false;  // NHC applies
  double nhc_lateral_std_mps = 0.1;
  double nhc_vertical_std_mps = 0.1;
  double nhc_min_speed_mps = 1.0;
  double gyro_arw_rad_rts = 1e-4;   // white noise of the IMU (preintegration weights)
  double accel_vrw_mps_rts = 1e-3;
  // Multiplier on the white-noise variances above, found by calibrate() from the IMU factors' own
  // residuals (vibration far above the data sheet); 1 at the start.
  double imu_noise_scale = 1.0;
  // Bias drift as a random walk's density (per sqrt(s)): the allowance per interval and between
  // bias segments (bias_segments.hpp).
  double gyro_bias_std_rps = 1e-5;
  double accel_bias_std_mps2 = 1e-4;
  double gnss_velocity_std_scale = 1.0;
  double gyro_scale_std = 1000e-6;  // prior std of the scale-factor errors (fraction)
  double accel_scale_std = 1000e-6;
};

struct CalibrationLog {
  CalibrationSetup setup;
  std::vector<ImuSample> imu;           // time order, IMU clock
  std::vector<GnssPosition> positions;  // primary antenna, GNSS time base, covariance scaled as the filter does
  std::vector<GnssVelocity> velocities;
  std::vector<GnssHeading> headings;    // dual-antenna, GNSS time base
  // External aiding (MIP 0x13 semantics), GNSS time base (their configured offset added); a
  // velocity in the vehicle frame goes through the mounting (vehicle_velocity_factor.hpp).
  std::vector<ExternalPosition> external_positions;
  std::vector<ExternalVelocity> external_velocities;
  std::vector<ExternalHeading> external_headings;
  std::vector<SpeedSample> speeds;
  std::vector<TrajectoryPoint> trajectory;  // smoothed, time order, IMU clock
};

}  // namespace navfuse::calib

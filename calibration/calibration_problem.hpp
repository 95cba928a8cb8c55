// The batch calibration over a whole log (Ceres): states at the GNSS epochs tied by IMU
// preintegration (preintegration_factor.hpp), GNSS position and velocity through the lever arm and
// the IMU clock offset, dual-antenna heading through the mounting (gnss_factors.hpp; external
// aiding's positions, velocities and headings through the same factors at their own lever arms,
// its vehicle-frame velocities through the mounting: vehicle_velocity_factor.hpp), wheel speed
// with an odometer scale and the non-holonomic constraint through the mounting
// (odometry_factors.hpp), robust (Huber) losses on every aiding residual so outliers do not drag
// the fit. The states start from the smoothed solution (filter/smoother); the installation from
// the configuration.
//
// Epochs: the IMU sample nearest each GNSS fix (on the IMU clock, through the configured offset);
// where fixes are further apart than max_epoch_spacing_s (outages, 1 Hz receivers) samples are
// added so odometry and NHC are seen throughout. An IMU gap longer than max_imu_gap_s breaks the
// chain: the pieces share only the calibration parameters.
//
// Estimated: lever arm, mounting pitch and yaw about the vehicle axes (when odometry, NHC, a
// dual-antenna heading or a vehicle-frame velocity sees them; the vehicle roll is held;
// mounting_rotation.hpp), the IMU time offset, the odometer scale (with wheel speeds), gyro and
// accelerometer biases (constant within segments of the log joined by the configured drift,
// bias_segments.hpp; the drift inside an interval is allowed for in the preintegration
// covariance) and scale factors (constant). Their std devs come from ceres::Covariance, scaled up by the fit's variance factor
// when residuals are larger than their stated noise (never down).
#pragma once

#include "calibration/bias_segments.hpp"
#include "calibration/calibration_log.hpp"
#include "calibration/calibration_result.hpp"

namespace navfuse::calib {

struct CalibrationOptions {
  double max_epoch_spacing_s = 0.5;
  double max_imu_gap_s = 1.0;
  // The epochs' rate and acceleration (the first-order time shifts' knowns) are the smoothed
  // trajectory's change over +-this (calibration_epochs.cpp); 0 takes the epoch's IMU sample.
  double knowns_half_window_s = 0.125;
  int max_iterations = 50;
  double huber_sigmas = 2.0;  // whitened residual beyond which a loss grows linearly
  double lever_arm_prior_std_m = 0.5;  // around the configured lever arm (gnss_factors.hpp VectorPrior)
  // On the residual pitch and yaw about the configured mounting, in every pass: an installer's
  // few degrees. Without it an angle no residual sees wanders (30 deg on parking_drive with
  // positions-only fixes while the mounting was the Euler pitch, which for that sensor was a
  // vehicle roll).
  double mounting_prior_std_rad = 5.0 * 3.14159265358979323846 / 180.0;
  int threads = 2;
  int max_passes = 8;               // relinearisations about the estimated time offset
  double offset_tolerance_s = 2e-4;  // ... until it moves less than this
  // IMU noise re-weighting between passes (calibrate()): the preintegration variances are scaled
  // by the IMU factors' variance factor while it exceeds `imu_variance_threshold`, up to
  // `max_imu_noise_scale` in all (1e4: std x 100, beyond anything vibration does to a bolted IMU).
  double imu_variance_threshold = 1.5;
  double max_imu_noise_scale = 1e4;
  // Each IMU factor's white noise is at least what the samples around it show (imu_white_noise.hpp:
  // vibration), measured in blocks as long as its interval over this long a window centred on it
  // (8 intervals when longer: vibration follows speed, so the window stays short); 0 uses the
  // data sheet's figures alone.
  double imu_noise_window_s = 4.0;
  BiasSegmentOptions bias_segments;
};

// Never throws on bad data: a log that cannot be calibrated comes back with `message` saying why
// and converged = false.
CalibrationResult calibrate(const CalibrationLog& log, const CalibrationOptions& options = {});

}  // namespace navfuse::calib

// The error-state vector of the EKF: every index is defined here and nowhere else.
//
// Error convention (Shin 2005 thesis §2.3; the "psi-angle" form of Groves 2nd ed. §14.2): an error
// is estimate minus truth, dx = x_hat - x, so a correction is applied by subtracting it. The
// attitude error phi is the small rotation, in NED, with C_nb_true = (I + [phi x]) C_nb_hat.
//
// The core 15 states are always on. Optional states are switched by FilterOptions::states; their
// indices are fixed anyway (a disabled state keeps zero covariance, so it never receives a gain)
// and the EKF works on the leading `active_dimension()` block, so the common configurations
// (core + wheel scale factor) pay only for what they use.
#pragma once

#include <Eigen/Core>

namespace navfuse::filter {

namespace sx {
inline constexpr int kPos = 0;         // position error, NED, m (3)
inline constexpr int kVel = 3;         // velocity error, NED, m/s (3)
inline constexpr int kAtt = 6;         // attitude error phi, NED, rad (3)
inline constexpr int kGyroBias = 9;    // gyro bias error, vehicle frame, rad/s (3)
inline constexpr int kAccelBias = 12;  // accelerometer bias error, vehicle frame, m/s^2 (3)
inline constexpr int kCoreCount = 15;
inline constexpr int kWheelScale = 15;  // odometer scale factor error, dimensionless (1)
inline constexpr int kMountPitch = 16;  // residual IMU-to-vehicle pitch, rad (1)
inline constexpr int kMountYaw = 17;    // residual IMU-to-vehicle yaw, rad (1)
inline constexpr int kLeverArm = 18;    // primary GNSS antenna lever arm error, vehicle frame, m (3)
inline constexpr int kGyroScale = 21;   // gyro scale factor errors, dimensionless (3)
inline constexpr int kAccelScale = 24;  // accelerometer scale factor errors, dimensionless (3)
// Residual GNSS time offset, s (1): what is still to be added to the GNSS timestamps (after
// gnss.time_offset_s) to put the fixes on the IMU's time. Last, so that it costs nothing unless
// switched on.
inline constexpr int kGnssTimeOffset = 27;
inline constexpr int kCount = 28;       // the largest state set
// Position, velocity and attitude are the only states with dynamics: every row of the system
// matrix F below this index may be non-zero, every row from it on is zero (biases and
// calibration states are random walks / constants). The covariance step exploits it.
inline constexpr int kDynamicCount = kGyroBias;

// Attitude rows: north, east, down tilt/heading components of phi.
inline constexpr int kAttDown = kAtt + 2;
}  // namespace sx

using StateVector = Eigen::Matrix<double, sx::kCount, 1>;
using Covariance = Eigen::Matrix<double, sx::kCount, sx::kCount>;

// Which optional states are estimated.
struct StateSelection {
  bool wheel_scale = true;      // odometer / wheel-speed scale factor
  bool mounting = false;        // residual IMU-to-vehicle pitch and yaw (seen by odometry, NHC)
  bool gnss_lever_arm = false;  // primary antenna lever arm
  bool gyro_scale = false;
  bool accel_scale = false;
  bool gnss_time_offset = false;  // residual GNSS-to-IMU time offset

  bool is_active(int index) const {
    if (index < sx::kCoreCount) return true;
    if (index == sx::kWheelScale) return wheel_scale;
    if (index == sx::kMountPitch || index == sx::kMountYaw) return mounting;
    if (index < sx::kLeverArm + 3) return gnss_lever_arm;
    if (index < sx::kGyroScale + 3) return gyro_scale;
    if (index < sx::kAccelScale + 3) return accel_scale;
    return gnss_time_offset;
  }
  // One past the highest active index: the block the EKF computes on.
  int active_dimension() const {
    if (gnss_time_offset) return sx::kGnssTimeOffset + 1;
    if (accel_scale) return sx::kAccelScale + 3;
    if (gyro_scale) return sx::kGyroScale + 3;
    if (gnss_lever_arm) return sx::kLeverArm + 3;
    if (mounting) return sx::kMountYaw + 1;
    if (wheel_scale) return sx::kWheelScale + 1;
    return sx::kCoreCount;
  }
};

}  // namespace navfuse::filter

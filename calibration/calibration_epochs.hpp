// Where the calibration puts its states (calibration_problem.hpp): IMU samples at the GNSS fixes
// and between fixes further apart than the spacing, each with its starting value from the
// smoothed trajectory in the tangent frame, and the knowns the aiding factors take there.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "calibration/calibration_log.hpp"
#include "calibration/gnss_factors.hpp"
#include "calibration/local_frame.hpp"

namespace navfuse::calib {

struct Epoch {
  std::size_t imu_index = 0;  // the IMU sample the state is at
  std::int64_t time_ns = 0;   // its stamp (IMU clock)
  geo::Llh llh;               // starting position (for gravity)
  std::array<double, 3> p{}, v{};
  std::array<double, 4> q{};  // Eigen order x y z w, tangent <- sensor
  EpochKnowns knowns;
  bool chained = false;       // an IMU factor links it to the previous epoch
};

// The IMU sample's angular rate and specific force (rates, or increments over their dt).
struct ImuRates {
  Eigen::Vector3d gyro_rps, accel_mps2;
  double dt_s;  // the interval the sample covers
};
ImuRates imu_rates(const std::vector<ImuSample>& imu, std::size_t i);

// The sample's increments as the preintegration takes them: the attitude change's rotation vector
// and the velocity change in the body frame at the interval's start. A device's compensated
// increments are that already (ImuIncrements::kCompensated); raw integrals and rates get the
// rotation term dtheta x dv / 2 and the two-sample coning and sculling terms with the previous
// sample (Savage 1998; the filter's strapdown_step adds the same), without which every turn
// biases the velocity by ~1e-3 m/s^2 (tests/filter/strapdown_sim_test.cpp). Their bias and
// scale-factor sensitivity is left out of the preintegration's Jacobians (second order).
struct StartFrameIncrements {
  Eigen::Vector3d dtheta_rad, dvel_mps;
  double dt_s;
};
StartFrameIncrements start_frame_increments(const std::vector<ImuSample>& imu, std::size_t i);

// Index of the IMU sample nearest `time_ns` (IMU clock); imu must be non-empty and time ordered.
std::size_t nearest_imu(const std::vector<ImuSample>& imu, std::int64_t time_ns);

struct EpochPlan {
  std::vector<Epoch> epochs;
  Eigen::Vector3d bg0 = Eigen::Vector3d::Zero(), ba0 = Eigen::Vector3d::Zero();  // sensor frame
};

// Epochs in time order; none when the trajectory or fixes do not overlap the IMU samples.
// `setup` is the installation to linearise about (the log's, or a previous pass's estimate): its
// time offset places the fixes on the IMU clock, and the trajectory, made with the log's
// configured offset, is read that much later (its state at a stamp is where the filter put the
// GNSS time stamp + configured offset).
EpochPlan plan_epochs(const CalibrationLog& log, const CalibrationSetup& setup, const LocalFrame& frame,
                      double max_spacing_s, double max_imu_gap_s, double knowns_half_window_s);

}  // namespace navfuse::calib

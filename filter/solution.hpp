// NavSolution from the filter state: what front-end encoders map to FusionEngine Pose and MIP 0x82.
//
// Two steps: capture_solution() copies out of the filter what a solution is computed from (a
// few hundred bytes: the state, five 3 x 3 covariance blocks, mode, validity and status words),
// and fill_nav_solution() does the arithmetic (attitude conversions, geoid, standard deviations).
// The split lets replay capture at every IMU epoch on the filter thread and fill on its output
// thread (apps/output/pose_output_thread.hpp); the result is the same either way.
#pragma once

#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

// What the fields that follow from a state and its covariance are computed from.
struct StateFieldInputs {
  NavState x;
  // Blocks of P.
  Eigen::Matrix3d pos_cov = Eigen::Matrix3d::Zero(), vel_cov = Eigen::Matrix3d::Zero(),
                  att_cov = Eigen::Matrix3d::Zero(), gyro_bias_cov = Eigen::Matrix3d::Zero(),
                  accel_bias_cov = Eigen::Matrix3d::Zero();
  // Sensor -> vehicle (mounting): biases are reported in the sensor frame.
  Eigen::Matrix3d c_vs = Eigen::Matrix3d::Identity();
  Eigen::Vector3d rate_b_rps = Eigen::Vector3d::Zero(), force_b_mps2 = Eigen::Vector3d::Zero(),
                  gravity_ned_mps2 = Eigen::Vector3d::Zero();
  // The calibration states' variances (their values are in x) and which are estimated: the stds
  // are taken on the thread that fills the solution, not on the filter's.
  Eigen::Matrix<double, sx::kCount - sx::kCoreCount, 1> calibration_var =
      Eigen::Matrix<double, sx::kCount - sx::kCoreCount, 1>::Zero();
  StateSelection states{};
};

// `c_vs` is the sensor-to-vehicle rotation of FilterOptions::mounting_rpy_rad (rot::dcm_from_rpy),
// which the engine holds anyway (ImuInput::mounting). `states`: which calibration states are
// estimated (the others are reported as not estimated).
void capture_state_fields(const NavState& x, const Covariance& p, const Eigen::Vector3d& rate_b_rps,
                          const Eigen::Vector3d& force_b_mps2, const Eigen::Vector3d& gravity_ned_mps2,
                          const Eigen::Matrix3d& c_vs, const StateSelection& states, StateFieldInputs& in);

// The fields that follow from a state and its covariance: position (and undulation), velocity,
// attitude, their stds, biases in the sensor frame with stds, gravity, compensated rate and
// gravity-free acceleration. Shared by the forward solution and the smoothed one.
void fill_state_fields(const StateFieldInputs& in, NavSolution& out);

struct SolutionInputs {
  MeasurementHeader header;  // time, time source; valid bits except undulation (fill_state_fields)
  NavMode mode = NavMode::kInvalid;
  GnssFixType gnss_fix = GnssFixType::kNone;
  std::uint32_t status_flags = 0;
  bool heading_known = false;  // else the heading std is that of no knowledge
  StateFieldInputs state;
};

void capture_solution(const FilterCore& core, const FilterOptions& o, const Eigen::Matrix3d& c_vs,
                      TimeSource time_source, SolutionInputs& in);
void fill_nav_solution(const SolutionInputs& in, NavSolution& out);

}  // namespace navfuse::filter

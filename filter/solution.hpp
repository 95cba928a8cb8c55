// NavSolution from the filter state: what front-end encoders map to FusionEngine Pose and MIP 0x82.
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

// The fields that follow from a state and its covariance: position (and undulation), velocity,
// attitude, their stds, biases in the sensor frame with stds, gravity, compensated rate and
// gravity-free acceleration. Shared by the forward solution and the smoothed one.
// `c_vs` is the sensor-to-vehicle rotation of FilterOptions::mounting_rpy_rad (rot::dcm_from_rpy),
// which the engine holds anyway (ImuInput::mounting): biases are reported in the sensor frame.
void fill_state_fields(const NavState& x, const Covariance& p, const Eigen::Vector3d& rate_b_rps,
                       const Eigen::Vector3d& force_b_mps2, const Eigen::Vector3d& gravity_ned_mps2,
                       const Eigen::Matrix3d& c_vs, NavSolution& out);

void fill_nav_solution(const FilterCore& core, const FilterOptions& o, const Eigen::Matrix3d& c_vs,
                       TimeSource time_source, NavSolution& out);

}  // namespace navfuse::filter

// The accelerometer as a gravity reference (tilt aiding): with the vehicle's own acceleration small
// against gravity, the specific force the accelerometers measure is gravity seen from the body,
// f_b = -C_bn g_n (Groves 2nd ed. §5.6.2, "levelling", and §16.2.1's attitude and heading
// reference systems, which take roll and pitch from it while nothing else observes velocity).
// What the vehicle's acceleration adds is the measurement's noise (control/tilt_control.hpp).
#pragma once

#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

// h(x): the raw vehicle-frame specific force an IMU at rest reads, (1 + s_a) (-C_bn g_n) + b_a.
Eigen::Vector3d gravity_specific_force_mps2(const StateView& s);

// `mean_raw_force_b_mps2`: the uncompensated vehicle-frame specific force averaged over a window.
// Rows x, y carry roll and pitch (and the horizontal biases, inseparable from them at one
// attitude); row z the vertical bias. The heading does not enter (gravity is vertical).
Observation gravity_vector_observation(const StateView& s, const Eigen::Vector3d& mean_raw_force_b_mps2,
                                       double std_mps2);

}  // namespace navfuse::filter

// GNSS antenna velocity: v_ant = v + C_nb (w_ib x l) - w_ie x (C_nb l) (Groves 2nd ed. §14.3.1,
// lever-arm velocity model).
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

// Antenna velocity in NED for a lever arm and its Jacobian rows (also used by external velocity).
Observation antenna_velocity_observation(const StateView& s, const Eigen::Vector3d& lever_arm_m,
                                         const Eigen::Vector3d& measured_ned_mps,
                                         bool lever_arm_is_state);

Observation gnss_velocity_observation(const StateView& s, const GnssVelocity& m);

}  // namespace navfuse::filter

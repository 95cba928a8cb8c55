// When the accelerometer's gravity reference is fused (the model is measurements/gravity_vector.hpp).
//
// An INS keeps its roll and pitch through velocity: a tilt error turns gravity into a horizontal
// acceleration that GNSS, odometry or a stop soon contradicts. Without any of them (an IMU on its
// own, a vertical gyro, an AHRS with a magnetometer: modes vertical_gyro and ahrs) nothing does,
// and the tilt follows the gyro biases away (the shared MicroStrain capture: roll 5 deg off the
// device's own within 90 s). Then the mean specific force over a short window is taken as gravity
// (Groves 2nd ed. §16.2.1), the vehicle's own acceleration counted as noise
// (accel_tilt.std_mps2), and windows whose specific force differs from g by more than
// accel_tilt.max_deviation_mps2 (a manoeuvre) are left out. Never while the filter navigates or any
// velocity evidence is recent (gnss.timeout_s): there the acceleration of a turning car would be
// read as tilt, where the INS knows better.
#pragma once

#include "filter/filter_core.hpp"

namespace navfuse::filter {

// Called after each propagated IMU interval (raw increments, vehicle frame).
void update_accel_tilt(FilterCore& core, const FilterOptions& o, const ImuIncrement& raw);

}  // namespace navfuse::filter

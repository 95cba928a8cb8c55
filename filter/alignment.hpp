// Initialisation: levelling while stationary (roll and pitch from the mean specific force,
// Groves 2nd ed. §5.6.2 "self-alignment"; MIP §6.4 "pitch/roll from the accelerometers"), and the
// ways the heading and position are first set (dual antenna, external or configured heading,
// kinematic alignment from the GNSS course above 2 m/s).
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

// Accumulates stationary IMU data before levelling; levels when enough is seen.
void feed_leveller(FilterCore& core, const FilterOptions& o, const ImuIncrement& raw);

// Roll and pitch from a mean specific force (vehicle frame). `stationary` selects the
// covariance: the tilt error of a stationary levelling is the accelerometer bias over g, exactly
// correlated with the bias error; otherwise a loose 2 deg.
void level(FilterCore& core, const FilterOptions& o, const Eigen::Vector3d& mean_force_b,
           double averaging_time_s, bool stationary);

// Replaces the heading, keeping roll and pitch, and forgets the heading's correlations.
void set_heading(FilterCore& core, double yaw_rad, double std_rad);

// Places the vehicle reference point at a GNSS antenna fix (through the lever arm), resetting the
// position covariance to the fix's, inflated by the lever arm while the heading is unknown.
void place_at_fix(FilterCore& core, const FilterOptions& o, const GnssPosition& fix);

}  // namespace navfuse::filter

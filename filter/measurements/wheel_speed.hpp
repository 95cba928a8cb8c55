// Odometry: the forward speed of the wheel measurement point (e.g. the rear-axle centre) in the
// odometry frame, scaled by the odometer scale factor: s = (1 + k) e_x^T R_m (C_nb^T v + w_eb x l)
// (Groves 2nd ed. §6.3 / §14.3.4, odometer aiding; MIP "total scale = SF + SF x SF error").
#pragma once

#include <optional>

#include "core/measurements/measurements.hpp"
#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

struct SpeedReading {
  double speed_mps = 0.0;  // signed, positive forward
  double std_mps = 0.0;
};

// The axle-centre speed from four wheel speeds: the mean of the rear wheels (unsteered, so their
// mean is exactly the axle-centre speed in a turn); the front pair only if the rear is missing,
// with the std doubled for steering. nullopt when no pair is valid.
std::optional<SpeedReading> speed_from_wheels(const WheelSpeeds& m, double default_std_mps);
std::optional<SpeedReading> speed_from_vehicle(const VehicleSpeed& m, double default_std_mps);

Observation wheel_speed_observation(const StateView& s, const SpeedReading& reading,
                                    const Eigen::Vector3d& lever_arm_m);

}  // namespace navfuse::filter

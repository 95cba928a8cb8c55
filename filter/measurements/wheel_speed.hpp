// Odometry: the forward speed of the wheel measurement point (e.g. the rear-axle centre) in the
// odometry frame, scaled by the odometer scale factor: s = (1 + k) e_x^T R_m (C_nb^T v + w_eb x l)
// (Groves 2nd ed. §6.3 / §14.3.4, odometer aiding; MIP "total scale = SF + SF x SF error").
//
// Odometry is fused at the end of the covariance step its time falls in (measurement_kinds.hpp,
// FuseTime::kCovarianceGrid), so the state can be up to a covariance interval (50 ms) newer than
// the speed: the prediction is moved back over the view's shift at the point's forward
// acceleration a, s(t + shift) = (1 + k) (e_x^T v_wheel + a shift). At 1 m/s^2 the shift alone is
// 5 cm/s, as large as a wheel speed's noise.
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

// The forward acceleration of the measurement point, in the vehicle frame: the time derivative of
// C_nb^T v + w x l with the rate held, f + C_nb^T g - w x (C_nb^T v) (Coriolis, transport rate and
// the angular acceleration left out: below 2e-3 m/s^2 at 30 m/s, and 0.5 rad/s^2 x |l|, the
// speed of a yaw-rate change, which a 50 ms shift turns into less than 3 cm/s at a 1.2 m lever).
// The lateral term matters in a turn: a rear axle 1.2 m behind the IMU gives the IMU a lateral
// speed of w_z 1.2 m, and -w x v_b a forward acceleration of w_z^2 1.2 m (0.3 m/s^2 at 0.5 rad/s).
double forward_accel_mps2(const StateView& s, const Eigen::Vector3d& force_b_mps2);

// `point_accel_mps2` (a, forward_accel_mps2() of the newest compensated specific force) is a
// constant of the update, like the view's rate in the lever-arm term: its dependence on the state
// (the tilt through C_nb^T g) times |shift| <= 50 ms is below g |shift| = 0.5 mm/s per mrad of
// tilt, far below the speed noise; H leaves it out.
Observation wheel_speed_observation(const StateView& s, const SpeedReading& reading,
                                    const Eigen::Vector3d& lever_arm_m, double point_accel_mps2);

}  // namespace navfuse::filter

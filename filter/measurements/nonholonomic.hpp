// Non-holonomic constraint for a land vehicle: at the rear-axle centre a wheeled vehicle neither
// slides sideways nor leaves the road, so the odometry-frame velocity there has zero y and z
// (Shin 2005 thesis §5.3; Groves 2nd ed. §14.3.4; MIP §6.7 "body velocity Y = 0 (and Z = 0)").
//
// Where that point is only guessed (a config without it: the IMU), the guess's error d moves the
// predicted velocity by w_eb x d (the lever-arm term of body_velocity_at), so a point known to
// sigma_l per axis adds J diag(sigma_l^2) J^T to the noise, J = [w_eb x] rows y and z: nothing on
// a straight road, 1.5 m x 7.5 deg/s = 0.2 m/s sideways in a turn (the unknown-parameter noise of
// a "consider" analysis, Maybeck vol. 1 §6.11, here with the parameter's prior only). The small
// mounting residual rotation R_m is left out of J (it turns d by under a degree).
#pragma once

#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

Observation nonholonomic_observation(const StateView& s, const Eigen::Vector3d& lever_arm_m,
                                     const Eigen::Vector3d& lever_arm_std_m, double lateral_std_mps,
                                     double vertical_std_mps);

}  // namespace navfuse::filter

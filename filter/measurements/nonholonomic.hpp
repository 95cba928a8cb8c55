// Non-holonomic constraint for a land vehicle: at the rear-axle centre a wheeled vehicle neither
// slides sideways nor leaves the road, so the odometry-frame velocity there has zero y and z
// (Shin 2005 thesis §5.3; Groves 2nd ed. §14.3.4; MIP §6.7 "body velocity Y = 0 (and Z = 0)").
#pragma once

#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

Observation nonholonomic_observation(const StateView& s, const Eigen::Vector3d& lever_arm_m,
                                     double lateral_std_mps, double vertical_std_mps);

}  // namespace navfuse::filter

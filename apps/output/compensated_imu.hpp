// The bias-compensated IMU measurement a navigation device reports beside its pose (FusionEngine
// IMUOutput 11000, NAVFUSE_IMU), rebuilt from the filter's solution: angular rate as is, specific
// force f_b = a_b - C_bn g_n (the solution carries the gravity-free acceleration a_b and g_n),
// both in the vehicle frame, as rates at the solution's time.
#pragma once

#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

// False (and `out` untouched) when the attitude is not yet known.
bool compensated_imu_from(const NavSolution& s, ImuSample& out);

}  // namespace navfuse::apps

// Zero-velocity (ZUPT) and zero-angular-rate (ZARU) updates for a stationary vehicle (Groves 2nd
// ed. §15.3.1, "zero velocity update" and "zero angular rate update"; MIP §6.7).
#pragma once

#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

// v_n = 0.
Observation zero_velocity_observation(const StateView& s, double std_mps);

// A stationary IMU measures only the earth rate: h(x) = mean raw gyro = b_g + C_nb^T w_ie.
Eigen::Vector3d stationary_raw_rate_rps(const StateView& s);
inline constexpr std::array<NeglectedTerm, 1> kZeroRateNeglected{{
    {0, 3, sx::kGyroScale, 3, geo::wgs84::kEarthRate_radps, "gyro scale error times the earth rate, diag(C^T w_ie): |w_ie|"},
}};
// `mean_raw_rate_b_rps` is the uncompensated vehicle-frame rate averaged over `window_s`.
Observation zero_rate_observation(const StateView& s, const Eigen::Vector3d& mean_raw_rate_b_rps,
                                  double std_rps);

}  // namespace navfuse::filter

// GNSS antenna velocity: v_ant = v + C_nb (w_ib x l) - w_ie x (C_nb l) (Groves 2nd ed. §14.3.1,
// lever-arm velocity model).
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/measurements/gnss_position.hpp"
#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

// h(x): the velocity in NED of a point at a lever arm (the antenna; external velocity too).
Eigen::Vector3d antenna_velocity_ned_mps(const StateView& s, const Eigen::Vector3d& lever_arm_m);

// H leaves out what body_velocity_at does, and the earth-rate part of the lever-arm Jacobian.
inline constexpr std::array<NeglectedTerm, 4> kAntennaVelocityNeglected{{
    kLeverRateEarthTerm, kLeverRateBiasScale, kLeverRateGyroScale,
    {0, 3, sx::kLeverArm, 3, geo::wgs84::kEarthRate_radps, "earth-rate part of the lever-arm velocity, -[w_ie x] C: |w_ie|"},
}};
// The NED axes an ECEF velocity is rotated from turn with position: |v| / R per metre.
inline constexpr NeglectedTerm kEcefAxesTurn{0, 3, sx::kPos, 3, 1e-5,
                                             "ECEF axes C_en turning with position: |v| / R for |v| <= 60 m/s"};

// Its residual against a measurement and its Jacobian rows.
Observation antenna_velocity_observation(const StateView& s, const Eigen::Vector3d& lever_arm_m,
                                         const Eigen::Vector3d& measured_ned_mps,
                                         bool lever_arm_is_state);

Observation gnss_velocity_observation(const StateView& s, const GnssVelocity& m, const Antenna& antenna);

}  // namespace navfuse::filter

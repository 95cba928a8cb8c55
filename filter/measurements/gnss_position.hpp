// GNSS antenna position: p_ant = p + C_nb l (Groves 2nd ed. §14.3.1, lever-arm position model),
// moved along the antenna velocity by the estimated GNSS time offset (Groves §14.3.2's
// time-synchronisation error, modelled as a state as in Li et al. 2017, "Online temporal
// calibration for camera-IMU", for a shift small against the dynamics).
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

// 1-sigma position noise assumed when a fix reports no covariance (typical receiver figures).
Eigen::Vector3d default_gnss_position_std_m(GnssFixType fix);
// The fix's NED covariance: the receiver's own when it reports one, else the default for its fix
// type; times std_scale^2 (gnss.std_scale_* of the configuration). One choice for the update and
// for placing the filter at a fix.
Eigen::Matrix3d gnss_position_cov_m2(const GnssPosition& m, double std_scale = 1.0);

// The antenna a receiver's fixes are measured at. Receiver 1 (MIP 0x92 "GNSS 2", VN-300 GNSS2:
// the second antenna of a dual-antenna set-up) is at the configured secondary antenna, a fixed
// lever arm; every other receiver, and receiver 1 while no secondary antenna is configured (zero),
// at the primary antenna, whose lever arm is the state sx::kLeverArm.
struct Antenna {
  Eigen::Vector3d lever_arm_m = Eigen::Vector3d::Zero();
  bool lever_arm_is_state = true;
};
Antenna antenna_of_receiver(const NavState& x, const Eigen::Vector3d& secondary_lever_arm_m,
                            std::uint8_t receiver_id);

// h(x): the antenna position at the fix's time on the IMU clock, t + dt (dt: the time offset state),
// p + C_nb l + v_ant (shift + dt).
PointPrediction gnss_position_prediction(const StateView& s, const Antenna& antenna);
// Rows north, east (and down when the height is valid).
Observation gnss_position_observation(const StateView& s, const GnssPosition& m, const Antenna& antenna);

}  // namespace navfuse::filter

// Heading from a three-axis magnetometer. The earth's field measured in the vehicle frame,
// rotated into NED with the estimated attitude, points at magnetic north: its azimuth is the
// declination D (Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation
// Systems, 2nd ed., §6.1.1, the tilt-compensated heading psi = psi_mb + D).
//
//   h(x) = azimuth(C_nb m_v),  z = D,  H = d azimuth / d phi_down only
//
// The roll and pitch columns of H (d azimuth / d phi_north, phi_east: about tan(inclination),
// 1.7 at 60 deg) are left out on purpose, as AHRS designs do (PX4 EKF2's heading fusion, MIP's
// magnetometer heading aiding): an uncalibrated hard or soft iron tilts the measured field by
// degrees, and with those columns the update turned it into roll and pitch. On the real MIP
// capture the tilt drifted 5 deg away from the device's own while standing still. Tilt is the
// accelerometers' (levelling, ZUPT) and GNSS's to estimate; the magnetometer only turns heading.
#pragma once

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "filter/ekf.hpp"
#include "filter/measurements/state_view.hpp"
#include "filter/neglected_term.hpp"

namespace navfuse::filter {

inline constexpr std::array<NeglectedTerm, 1> kMagneticHeadingNeglected{{
    {0, 1, sx::kAtt, 2, 12.0,
     "roll and pitch columns: the magnetometer must not tilt the attitude (|d az / d tilt| ~ "
     "tan(inclination), below 12 outside 5 deg of the magnetic poles)"},
}};

// `field_v`: the measured field in the vehicle frame (hard iron removed), any unit.
Observation magnetic_heading_observation(const StateView& s, const Eigen::Vector3d& field_v,
                                         double declination_rad, double std_rad);

// The heading (yaw, rad) at which a vehicle with the roll and pitch of `q_nb` sees `field_v`
// pointing at magnetic north: D - azimuth(C(roll, pitch, 0) m_v). For alignment.
double magnetic_heading_rad(const Eigen::Quaterniond& q_nb, const Eigen::Vector3d& field_v,
                            double declination_rad);

// |horizontal component| of `field_v` once levelled by the roll and pitch of `q_nb`.
double horizontal_field(const Eigen::Quaterniond& q_nb, const Eigen::Vector3d& field_v);

}  // namespace navfuse::filter

// Normal (ellipsoidal) gravity on WGS-84, from GeographicLib::NormalGravity (Karney's
// implementation of the closed-form normal potential, Heiskanen & Moritz §2-7), expressed in NED.
#pragma once

#include <Eigen/Core>

namespace navfuse::geo {

// Gravity (gravitation plus centrifugal) vector in NED at latitude/height, m/s^2. The north
// component is the small deflection of the normal above the ellipsoid (zero on it).
Eigen::Vector3d normal_gravity_ned(double lat_rad, double height_m);
// Magnitude on the ellipsoid surface (Somigliana's formula, TR8350.2 eq. 4-1).
double normal_gravity_surface_mps2(double lat_rad);

}  // namespace navfuse::geo

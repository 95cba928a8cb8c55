// Geodetic position, ECEF and the local NED frame on the WGS-84 ellipsoid, built on GeographicLib
// (C. F. F. Karney, "Transverse Mercator with an accuracy of a few nanometers" / Geocentric class
// documentation) for the exact conversions, with the closed-form quantities the filter needs per
// sample (radii of curvature, earth and transport rates) written out with their sources.
#pragma once

#include <Eigen/Core>

namespace navfuse::geo {

// Geodetic latitude and longitude in radians, height above the ellipsoid in metres.
struct Llh {
  double lat_rad = 0.0;
  double lon_rad = 0.0;
  double height_m = 0.0;
};

Eigen::Vector3d ecef_from_llh(const Llh& llh);
Llh llh_from_ecef(const Eigen::Vector3d& ecef_m);

// Rotation taking NED vectors at (lat, lon) into ECEF: v_ecef = C_en * v_ned.
Eigen::Matrix3d rot_ecef_from_ned(double lat_rad, double lon_rad);

// Radii of curvature (Groves, "Principles of GNSS, Inertial, and Multisensor Integrated
// Navigation Systems", 2nd ed., eqs. 2.105-2.106).
struct Radii {
  double meridian_m = 0.0;        // R_N (north-south), rho
  double prime_vertical_m = 0.0;  // R_E (east-west), nu
};
Radii radii_of_curvature(double lat_rad);

// Earth rotation rate expressed in NED at latitude (Groves eq. 5.41).
Eigen::Vector3d earth_rate_ned(double lat_rad);
// Transport rate: rotation of NED relative to the earth due to motion (Groves eq. 5.44).
Eigen::Vector3d transport_rate_ned(double lat_rad, double height_m, const Eigen::Vector3d& vel_ned_mps);

// Small displacement of `to` relative to `from` in `from`'s NED frame, exact through ECEF.
Eigen::Vector3d ned_offset_m(const Llh& from, const Llh& to);
// Position reached by moving `offset_ned_m` (in `from`'s NED frame) from `from`.
Llh llh_offset(const Llh& from, const Eigen::Vector3d& offset_ned_m);

}  // namespace navfuse::geo

#include "core/geodesy/geodesy.hpp"

#include <cmath>

#include <GeographicLib/Geocentric.hpp>

#include "core/geodesy/wgs84.hpp"

namespace navfuse::geo {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

const GeographicLib::Geocentric& wgs84_geocentric() {
  // Karney's Geocentric: exact forward and an inverse accurate to a few nm everywhere
  // (GeographicLib docs, "Geocentric coordinates"; Vermeille's closed-form method).
  static const GeographicLib::Geocentric g(wgs84::kSemiMajorAxis_m, wgs84::kFlattening);
  return g;
}

}  // namespace

Eigen::Vector3d ecef_from_llh(const Llh& llh) {
  Eigen::Vector3d x;
  wgs84_geocentric().Forward(llh.lat_rad * kRadToDeg, llh.lon_rad * kRadToDeg, llh.height_m,
                             x.x(), x.y(), x.z());
  return x;
}

Llh llh_from_ecef(const Eigen::Vector3d& ecef_m) {
  double lat_deg, lon_deg, h;
  wgs84_geocentric().Reverse(ecef_m.x(), ecef_m.y(), ecef_m.z(), lat_deg, lon_deg, h);
  return {lat_deg * kDegToRad, lon_deg * kDegToRad, h};
}

Eigen::Matrix3d rot_ecef_from_ned(double lat_rad, double lon_rad) {
  // Groves eq. 2.150 (C_n^e): columns are the north, east and down unit vectors in ECEF.
  const double sl = std::sin(lat_rad), cl = std::cos(lat_rad);
  const double so = std::sin(lon_rad), co = std::cos(lon_rad);
  Eigen::Matrix3d c;
  c << -sl * co, -so, -cl * co,
       -sl * so, co, -cl * so,
       cl, 0.0, -sl;
  return c;
}

Radii radii_of_curvature(double lat_rad) {
  const double s = std::sin(lat_rad);
  const double d = 1.0 - wgs84::kEccentricitySq * s * s;
  const double sqrt_d = std::sqrt(d);
  Radii r;
  r.meridian_m = wgs84::kSemiMajorAxis_m * (1.0 - wgs84::kEccentricitySq) / (d * sqrt_d);  // eq. 2.105
  r.prime_vertical_m = wgs84::kSemiMajorAxis_m / sqrt_d;                                   // eq. 2.106
  return r;
}

Eigen::Vector3d earth_rate_ned(double lat_rad) {
  return {wgs84::kEarthRate_radps * std::cos(lat_rad), 0.0, -wgs84::kEarthRate_radps * std::sin(lat_rad)};
}

Eigen::Vector3d transport_rate_ned(double lat_rad, double height_m, const Eigen::Vector3d& v) {
  const Radii r = radii_of_curvature(lat_rad);
  const double re_h = r.prime_vertical_m + height_m;
  return {v.y() / re_h, -v.x() / (r.meridian_m + height_m), -v.y() * std::tan(lat_rad) / re_h};
}

Eigen::Vector3d ned_offset_m(const Llh& from, const Llh& to) {
  const Eigen::Vector3d d = ecef_from_llh(to) - ecef_from_llh(from);
  return rot_ecef_from_ned(from.lat_rad, from.lon_rad).transpose() * d;
}

Llh llh_offset(const Llh& from, const Eigen::Vector3d& offset_ned_m) {
  return llh_from_ecef(ecef_from_llh(from) + rot_ecef_from_ned(from.lat_rad, from.lon_rad) * offset_ned_m);
}

}  // namespace navfuse::geo

#include "core/geodesy/gravity.hpp"

#include <cmath>

#include <GeographicLib/NormalGravity.hpp>

#include "core/geodesy/wgs84.hpp"

namespace navfuse::geo {

Eigen::Vector3d normal_gravity_ned(double lat_rad, double height_m) {
  // GeographicLib::NormalGravity::Gravity(lat, h, gammay, gammaz) gives the northerly and upward
  // components (gammaz < 0: gravity points down), centrifugal term included; the easterly
  // component vanishes by axial symmetry (NormalGravity.hpp documentation).
  static const GeographicLib::NormalGravity& g = GeographicLib::NormalGravity::WGS84();
  double gamma_north = 0.0, gamma_up = 0.0;
  g.Gravity(lat_rad * 180.0 / 3.14159265358979323846, height_m, gamma_north, gamma_up);
  return {gamma_north, 0.0, -gamma_up};
}

double normal_gravity_surface_mps2(double lat_rad) {
  // Somigliana: gamma = gamma_e (1 + k sin^2 phi) / sqrt(1 - e^2 sin^2 phi),
  // k = (b gamma_p - a gamma_e) / (a gamma_e) (TR8350.2 eq. 4-1).
  const double a = wgs84::kSemiMajorAxis_m, b = wgs84::kSemiMinorAxis_m;
  const double k = (b * wgs84::kGravityPole_mps2 - a * wgs84::kGravityEquator_mps2) /
                   (a * wgs84::kGravityEquator_mps2);
  const double s2 = std::sin(lat_rad) * std::sin(lat_rad);
  return wgs84::kGravityEquator_mps2 * (1.0 + k * s2) / std::sqrt(1.0 - wgs84::kEccentricitySq * s2);
}

}  // namespace navfuse::geo

// WGS-84 defining constants (NIMA TR8350.2, 3rd ed., Table 3.1) and the derived ones navfuse uses.
#pragma once

namespace navfuse::geo::wgs84 {

inline constexpr double kSemiMajorAxis_m = 6378137.0;                // a
inline constexpr double kFlattening = 1.0 / 298.257223563;           // f
inline constexpr double kEarthRate_radps = 7.292115e-5;              // omega_ie
inline constexpr double kGM_m3ps2 = 3.986004418e14;                  // GM (with atmosphere)
inline constexpr double kSemiMinorAxis_m = kSemiMajorAxis_m * (1.0 - kFlattening);  // b
inline constexpr double kEccentricitySq = kFlattening * (2.0 - kFlattening);         // e^2
// Normal gravity at the equator and the poles (TR8350.2 Table 3.4), m/s^2.
inline constexpr double kGravityEquator_mps2 = 9.7803253359;
inline constexpr double kGravityPole_mps2 = 9.8321849378;
// Standard gravity, for converting "g" units at protocol boundaries (CGPM 1901; MIP and VN both
// document their g scaling against 9.80665).
inline constexpr double kStandardGravity_mps2 = 9.80665;

}  // namespace navfuse::geo::wgs84

// Unit conversions at the MIP boundary (DESIGN.md: SI inside, convert at the protocol edge).
#pragma once

#include "core/geodesy/wgs84.hpp"

namespace navfuse::frontends::mip {

// Scaled accel is in g and delta velocity in g*s (L6393, L6437, errata E35). The spec gives no
// value of g for the conversion; standard gravity is used both ways so that encode/decode are
// exact inverses.
inline constexpr double kGravity_mps2 = geo::wgs84::kStandardGravity_mps2;
inline constexpr double kMbarToPa = 100.0;  // scaled pressure in mBar (L6515)

}  // namespace navfuse::frontends::mip

// When and how magnetometer readings are fused (the model is measurements/magnetic_heading.hpp).
// Only with `magnetometer.heading_std_deg` configured (Engine counts them ignored otherwise).
// - The reading is moved into the vehicle frame (hard iron removed in the sensor frame, then the
//   IMU mounting) and must look like the earth's field: total strength within
//   [min_field_gauss, max_field_gauss] and a usable horizontal part, else "magnetic_disturbance".
// - Declination: the configured one, else GeographicLib's model at the filter's position (cached
//   per ~10 km), else "no_declination".
// - Levelled but no heading yet: the tilt-compensated magnetic heading aligns the filter (MIP
//   §6.4's magnetometer heading source); with a heading, it is a gated 1-D update.
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

FuseResult fuse(FilterCore& core, const FilterOptions& o, const Magnetometer& m, double shift_s);

}  // namespace navfuse::filter

// Height from a barometer. Pressure becomes height with the International Standard Atmosphere
// (ICAO Doc 7488, troposphere: h = T0/L (1 - (p/p0)^(R L / g0)) with T0 = 288.15 K,
// L = 0.0065 K/m, p0 = 101325 Pa, R L / g0 = 0.190263). Weather moves that height by metres over
// hours, so it is only a relative height: the controller (control/baro_control.hpp) anchors it
// to the filter's height once, and this model compares the anchored height with the estimate.
//
//   h(x) = height of the nominal position (moved over the time shift),  z = anchored baro height
#pragma once

#include "filter/ekf.hpp"
#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

// ISA pressure altitude (m) of a static pressure (Pa).
double pressure_altitude_m(double pressure_pa);

// The height the model predicts for the IMU point (h(x)).
double baro_height_prediction_m(const StateView& s);

Observation baro_height_observation(const StateView& s, double height_m, double std_m);

}  // namespace navfuse::filter

// Automatic stationary detection and the zero-velocity / zero-angular-rate updates it enables
// (MIP §6.7). A window of IMU data is "quiet" when the mean compensated rate and the specific-force
// scatter are small (or, for a vibrating vehicle, a fresh speed measurement shows it at rest:
// speed_shows_rest) and the mean specific force has not changed since the vehicle stopped; the
// vehicle is stationary after two quiet windows in a row, provided no speed evidence (odometry,
// GNSS, or the filter's own velocity in navigation) says it moves: a simulated or very smooth
// cruise is as quiet as a parked car.
#pragma once

#include "filter/filter_core.hpp"

namespace navfuse::filter {

void update_stationary(FilterCore& core, const FilterOptions& o, const ImuIncrement& raw);

// A fresh speed measurement (within the last 0.5 s; the odometer's if there is one, else GNSS
// horizontal speed) puts the vehicle at rest: below half of zupt.max_speed_mps. What tells a car
// standing with its engine running (specific-force scatter far above the quiet threshold) from one
// that moves.
bool speed_shows_rest(const FilterCore& core, const FilterOptions& o);

}  // namespace navfuse::filter

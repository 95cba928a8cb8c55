// When wheel / vehicle speed and the non-holonomic constraint are fused: only in navigation
// (they say nothing useful before the heading is known), the constraint at a fixed rate while the
// vehicle moves (at rest ZUPT takes over, and at walking pace wheel slip and steering geometry
// dominate), both through a chi-square gate so a skid is rejected rather than believed.
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

FuseResult fuse(FilterCore& core, const FilterOptions& o, const WheelSpeeds& m, double shift_s);
FuseResult fuse(FilterCore& core, const FilterOptions& o, const VehicleSpeed& m, double shift_s);
// Tick counts (wheel or vehicle) as the mean speed since the stream's previous count
// (measurements/wheel_ticks.hpp) with the scale FilterOptions::wheel_m_per_tick.
FuseResult fuse(FilterCore& core, const FilterOptions& o, const WheelTicks& m, double shift_s);

// Called every IMU sample; fuses the constraint when it is due.
void apply_nonholonomic(FilterCore& core, const FilterOptions& o);

}  // namespace navfuse::filter

// Dual-antenna baseline check (issue 17): a land vehicle moving forward points along its course
// over ground (the premise of kinematic alignment, MIP §6.4), so the vehicle yaw the dual-antenna
// heading implies through the configured baseline must agree with the GNSS course while moving.
// A baseline configured wrong (antennas swapped: 180 deg; a mounting turned by 90 deg) makes them
// disagree by that offset at every epoch. After kMismatchesToFlag consecutive disagreeing epochs
// (about 2 s at 5 Hz, so well within 10 s of motion) the offset is flagged
// (NavSolution::kStatusHeadingOffset), GNSS heading is rejected from then on ("baseline_mismatch")
// and the heading is re-aligned from the course over ground.
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

// Notes the vehicle yaw implied by a dual-antenna heading (for the next course comparison).
void note_antenna_yaw(FilterCore& core, std::int64_t time_ns, double vehicle_yaw_rad);

// Compares the course of a GNSS velocity with the latest antenna yaw when the comparison means
// something (moving forward fast enough for a sharp course, recent antenna yaw, a land vehicle);
// true when this epoch flags the offset.
bool check_baseline(FilterCore& core, const FilterOptions& o, const GnssVelocity& m, double course_std_rad);

}  // namespace navfuse::filter

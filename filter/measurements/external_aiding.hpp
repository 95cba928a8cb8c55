// External aiding (MIP 0x13 semantics): position (LLH or ECEF), velocity (NED, ECEF or vehicle
// frame) and heading, each with per-axis validity and 1-sigma uncertainty, measured at a lever arm
// in the vehicle frame.
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

Observation external_position_observation(const StateView& s, const ExternalPosition& m);
Observation external_velocity_observation(const StateView& s, const ExternalVelocity& m);
Observation external_heading_observation(const StateView& s, const ExternalHeading& m);

}  // namespace navfuse::filter

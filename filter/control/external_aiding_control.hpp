// When external aiding (position, velocity, heading from other systems) is fused: positions count
// as absolute aiding for the navigation mode and may place the filter before any GNSS; headings
// may initialise the heading (MIP §6.4 "external" alignment source); everything is gated.
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

FuseResult fuse(FilterCore& core, const FilterOptions& o, const ExternalPosition& m, double shift_s);
FuseResult fuse(FilterCore& core, const FilterOptions& o, const ExternalVelocity& m, double shift_s);
FuseResult fuse(FilterCore& core, const FilterOptions& o, const ExternalHeading& m, double shift_s);

}  // namespace navfuse::filter

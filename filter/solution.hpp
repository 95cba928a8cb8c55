// NavSolution from the filter state: what front-end encoders map to FusionEngine Pose and MIP 0x82.
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

void fill_nav_solution(const FilterCore& core, const FilterOptions& o, TimeSource time_source,
                       NavSolution& out);

}  // namespace navfuse::filter

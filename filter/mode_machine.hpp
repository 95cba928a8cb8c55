// Filter modes, as MIP's filter states (MIP §6.2): Init -> Vertical Gyro (levelled) -> AHRS
// (absolute heading) -> Full Navigation (heading and position), with Dead Reckoning when absolute
// position aiding has been missing longer than FilterOptions::gnss_timeout_s.
#pragma once

#include "filter/filter_core.hpp"

namespace navfuse::filter {

void update_mode(FilterCore& core, const FilterOptions& o);

}  // namespace navfuse::filter

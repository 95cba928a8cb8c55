// The quality bar of DESIGN.md: a measurement with NaN/inf, an impossible value or an uncertainty
// <= 0 on a valid axis is rejected with a reason and never reaches the filter state.
#pragma once

#include <optional>

#include "core/measurements/measurements.hpp"
#include "filter/filter_stats.hpp"

namespace navfuse::filter {

std::optional<RejectReason> check_input(const Measurement& m);

}  // namespace navfuse::filter

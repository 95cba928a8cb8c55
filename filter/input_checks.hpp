// The quality bar of DESIGN.md: a measurement with NaN/inf, an impossible value or an uncertainty
// <= 0 on a valid axis is rejected with a reason and never reaches the filter state.
#pragma once

#include <optional>

#include "core/measurements/measurements.hpp"
#include "filter/filter_stats.hpp"

namespace navfuse::filter {

// One overload per kind the filter fuses (filter/measurement_kinds.hpp maps kinds to them).
std::optional<RejectReason> check_input(const ImuSample& m);
std::optional<RejectReason> check_input(const GnssPosition& m);
std::optional<RejectReason> check_input(const GnssVelocity& m);
std::optional<RejectReason> check_input(const GnssHeading& m);
std::optional<RejectReason> check_input(const WheelSpeeds& m);
std::optional<RejectReason> check_input(const VehicleSpeed& m);
std::optional<RejectReason> check_input(const WheelTicks& m);
std::optional<RejectReason> check_input(const ExternalPosition& m);
std::optional<RejectReason> check_input(const ExternalVelocity& m);
std::optional<RejectReason> check_input(const ExternalHeading& m);
std::optional<RejectReason> check_input(const Magnetometer& m);
std::optional<RejectReason> check_input(const Pressure& m);

}  // namespace navfuse::filter

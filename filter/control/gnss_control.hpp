// When and how GNSS is fused (kept apart from the measurement models, as PX4 EKF2's control
// files): fix-quality checks, use for initialisation before the heading is known (position and
// velocity resets, kinematic heading alignment at 2 m/s, MIP §6.4), chi-square innovation gates,
// and recovery after sustained rejection: when every fix for gnss_recovery_s has been rejected the
// filter trusts GNSS again and re-anchors to it rather than coasting away (MIP §6.6).
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

FuseResult fuse(FilterCore& core, const FilterOptions& o, const GnssPosition& m,
                              double shift_s);
FuseResult fuse(FilterCore& core, const FilterOptions& o, const GnssVelocity& m,
                              double shift_s);
FuseResult fuse(FilterCore& core, const FilterOptions& o, const GnssHeading& m,
                             double shift_s);

}  // namespace navfuse::filter

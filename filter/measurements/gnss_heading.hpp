// Dual-antenna heading: the azimuth of the primary-to-secondary baseline, C_nb b, in NED.
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

// Baseline from the two configured lever arms; the vehicle x axis when they coincide (a device
// that reports vehicle heading directly).
Eigen::Vector3d heading_baseline_b(const Eigen::Vector3d& primary_m, const Eigen::Vector3d& secondary_m);

Observation gnss_heading_observation(const StateView& s, const GnssHeading& m,
                                     const Eigen::Vector3d& baseline_b);

}  // namespace navfuse::filter

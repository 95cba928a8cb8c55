// Heading alignment from GNSS velocity while the heading is unknown (vertical-gyro mode):
// velocity matching (velocity_matching_alignment.hpp) for any platform that accelerates or turns,
// the course over ground for a land vehicle (MIP §6.4). The velocity is the receiver's own, or,
// for receivers that report positions only (RTKLIB .pos without velocity columns, KF-GINS-style
// GNSS text, NMEA GGA), the difference of two consecutive fixes: without it such a log never
// leaves vertical-gyro mode.
#pragma once

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

// A horizontal-and-vertical velocity offered for heading alignment.
struct AlignmentVelocity {
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov_m2ps2 = Eigen::Matrix3d::Identity();  // of the velocity as a measurement
  // For a velocity that is a mean over an interval: the velocity-matching force integral u
  // averaged over the same interval (nullopt: the velocity is at the current IMU time).
  std::optional<Eigen::Vector2d> force_integral_mps;
  // Variance added (per axis) when the velocity state is reset to it: the state is at the current
  // time, a mean velocity half an interval earlier.
  double state_reset_extra_var_m2ps2 = 0.0;
};

// Uses `v` to find the heading (velocity matching, then the course when o.course_alignment) and
// resets the velocity state to it; at rest restarts the velocity-matching window instead.
// Places the filter at the newest fix once the heading is set. kNotAligned when at rest.
FuseResult align_heading_from_velocity(FilterCore& core, const FilterOptions& o, const AlignmentVelocity& v,
                                       std::int64_t now_ns);

// The velocity between two fixes of one receiver with a height, (p1 - p0) / (t1 - t0), with the
// variance of the difference, (P0 + P1) / dt^2 (each P as the position update takes it: reported
// or by fix type, scaled by gnss.std_scale_*), when 0 < dt <= 2 s. `u0`, `u1`: the
// velocity-matching force integral at each fix; their mean pairs with the mean velocity.
std::optional<AlignmentVelocity> velocity_from_fixes(const FilterOptions& o, const GnssPosition& previous,
                                                     const Eigen::Vector2d& u0, const GnssPosition& current,
                                                     const Eigen::Vector2d& u1);

}  // namespace navfuse::filter

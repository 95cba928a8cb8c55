// Core types -> the navfuse LCM messages (core/lcm/*.lcm). Degrees and floats on the wire because
// that is what LCM consumers (plots, loggers) want to read directly; SI everywhere else.
// The conversions fill a caller-owned message so a publisher can reuse one per channel and the
// per-sample path does not allocate.
#pragma once

#include "core/measurements/measurements.hpp"
#include "navfuse/gnss_t.hpp"
#include "navfuse/imu_t.hpp"
#include "navfuse/pose_t.hpp"

namespace navfuse::apps {

void fill_pose(const NavSolution& s, navfuse::pose_t& out);

// The filter's bias-compensated angular rate and specific force in the vehicle frame at the
// solution's time (apps/output/compensated_imu.hpp). False before the attitude is known.
bool fill_imu(const NavSolution& s, navfuse::imu_t& out);

// A fix, with the velocity of the same epoch when one is given (nullptr: has_velocity = 0).
void fill_gnss(const GnssPosition& p, const GnssVelocity* v, navfuse::gnss_t& out);

}  // namespace navfuse::apps

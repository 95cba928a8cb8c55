// Multipath jumps: in a street canyon a receiver tracks reflected signals for a few seconds at a
// time, and its position jumps by decimetres to metres while the std devs it reports stay those
// of its fix type (its error model assumes direct signals; Groves §9.3.4 on multipath and NLOS
// reception, where NLOS ranging errors of tens of metres are possible and position errors of
// metres typical in urban areas). These are the fixes a filter must recognise as wrong.
//
// Events arrive as a Poisson process inside the given windows (the urban segments of a drive):
// each lasts a uniform time in [min_duration_s, max_duration_s] and displaces every fix inside
// it by a constant offset: horizontal magnitude log-uniform in [min_offset_m, max_offset_m] (so
// decimetre and metre jumps are equally common per decade), uniform azimuth, and a vertical
// part uniform in +-vertical_ratio times the horizontal magnitude. Events do not overlap.
// Velocity is left alone: Doppler-derived velocity is far less affected by a reflected path than
// the code ranges (a constant extra path length has no Doppler).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "apps/sim/time_interval.hpp"

namespace navfuse::sim {

struct MultipathSpec {
  std::vector<TimeInterval> windows;  // seconds since the scenario start
  double events_per_minute = 6.0;
  double min_offset_m = 0.2;
  double max_offset_m = 3.0;
  double vertical_ratio = 1.0;
  double min_duration_s = 1.0;
  double max_duration_s = 5.0;
};

struct MultipathEvent {
  TimeInterval interval;
  Eigen::Vector3d offset_ned_m = Eigen::Vector3d::Zero();
};

// The events of a spec, sorted by time; deterministic for a seed (own random stream).
std::vector<MultipathEvent> multipath_events(const MultipathSpec& spec, std::uint64_t seed);

// The offset in force at `t_s` (zero outside every event); `active` tells whether one is.
Eigen::Vector3d multipath_offset(const std::vector<MultipathEvent>& events, double t_s,
                                 bool* active = nullptr);

}  // namespace navfuse::sim

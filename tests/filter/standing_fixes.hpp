// A closed-form GNSS stream for the adaptation and step-check tests: standing still with a known
// heading, RTK-like fixes (2 cm, reported RTK fixed) at 5 Hz, each moved north of the truth by
// `north_m(t)` metres; what the filter made of it at the end.
#pragma once

#include <cstdint>
#include <functional>
#include <random>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"
#include "tests/filter/line_trajectory.hpp"

namespace navfuse::filter::test {

struct StandingOutcome {
  std::uint64_t gated = 0;       // rejected at the chi-square gate
  std::uint64_t jumps = 0;       // rejected as displaced by a step (gnss_jump)
  std::uint64_t used = 0;
  std::uint64_t inflations = 0;
  std::uint64_t recoveries = 0;
  double process_noise_scale = 0.0;  // at the end
  double final_north_m = 0.0;        // estimate minus truth
  double max_north_m = 0.0;          // largest |estimate minus truth| north, from 10 s on
};

inline StandingOutcome run_standing(FilterOptions o, double duration_s, const std::function<double(double)>& north_m) {
  constexpr double kLat = 40.0 * rot::kDegToRad;
  const Eigen::Vector3d rpy = Eigen::Vector3d(1.0, -2.0, 60.0) * rot::kDegToRad;
  o.initial_heading_rad = rpy.z();
  Engine e{o};
  LineTrajectory traj({kLat, 0.2, 100.0}, Eigen::Vector3d::Zero(), rpy, 200.0);
  std::mt19937_64 rng(11);
  StandingOutcome out;
  const auto north_error = [&] {
    return geo::ned_offset_m(traj.truth().llh, {e.solution().lat_rad, e.solution().lon_rad, e.solution().height_m}).x();
  };
  for (int k = 1; k <= static_cast<int>(duration_s * 200.0 + 0.5); ++k) {
    e.process(traj.next());
    const double t = k / 200.0;
    if (t >= 10.0) out.max_north_m = std::max(out.max_north_m, std::abs(north_error()));
    if (k % 40 != 0) continue;
    GnssPosition fix = make_fix(traj.truth(), Eigen::Vector3d::Zero(), 0.02, &rng);
    fix.fix = GnssFixType::kRtkFixed;
    const geo::Llh moved = geo::llh_offset({fix.lat_rad, fix.lon_rad, fix.height_m}, Eigen::Vector3d(north_m(t), 0, 0));
    fix.lat_rad = moved.lat_rad;
    e.process(Measurement{fix});
  }
  const FilterStats stats = e.stats();
  const KindStats& gnss = stats.of(MeasurementKind::kGnssPosition);
  out.gated = gnss.rejected_for(RejectReason::kChi2Gate);
  out.jumps = gnss.rejected_for(RejectReason::kGnssJump);
  out.used = gnss.used;
  out.inflations = stats.covariance_inflations;
  out.recoveries = stats.gnss_recoveries;
  out.process_noise_scale = stats.process_noise_scale;
  out.final_north_m = north_error();
  return out;
}

}  // namespace navfuse::filter::test

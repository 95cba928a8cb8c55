// Runs a simulator scenario through an Engine that records its forward pass, smooths the record
// and scores both the forward and the smoothed solution against the simulator's truth.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "apps/sim/simulator.hpp"
#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"
#include "filter/smoother/forward_record.hpp"
#include "filter/smoother/rts_smoother.hpp"

namespace navfuse::filter::test {

// The error of a state against truth: NED position (m), NED velocity (m/s), phi (rad), in the
// filter's estimate-minus-truth convention (state_layout.hpp).
struct TruthError {
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
  Eigen::Vector3d vel = Eigen::Vector3d::Zero();
  Eigen::Vector3d att = Eigen::Vector3d::Zero();
};

inline TruthError error_against(const sim::TruthSample& truth, double lat_rad, double lon_rad, double height_m,
                                const Eigen::Vector3d& vel_ned_mps, const Eigen::Quaterniond& q_nb) {
  TruthError e;
  e.pos = geo::ned_offset_m(truth.llh, {lat_rad, lon_rad, height_m});
  e.vel = vel_ned_mps - truth.vel_ned_mps;
  e.att = -rot::rotvec_from_quat(truth.q_nb * q_nb.conjugate());
  return e;
}

struct ForwardEpoch {
  sim::TruthSample truth;  // at the time the sample is stamped with (its true time less any IMU clock offset)
  TruthError error;        // of the forward solution
  bool navigating = false;
};

struct SmoothedRun {
  std::vector<ForwardEpoch> forward;  // every IMU epoch
  std::int64_t start_ns = 0;
  FilterStats stats;
  SmootherStats smoother;
  std::uint64_t record_bytes = 0, replaced = 0;
};

// `on_smoothed` sees each smoothed sample with the truth at its time and its error. Both the
// forward and the smoothed solution are scored against the truth at their timestamp: with an IMU
// clock offset (the scenario's imu.time_offset_s, not corrected) that is not the truth of the
// sample's true time, which the simulator reports, but the one the filter's GNSS pulls it to.
inline SmoothedRun run_smoothed(const sim::Scenario& scenario, const FilterOptions& options,
                                const std::function<void(const SmoothedSample&, const sim::TruthSample&,
                                                         const TruthError&)>& on_smoothed) {
  sim::Simulator sim(scenario);
  Engine engine(options);
  ForwardRecorder recorder;
  engine.record_to(&recorder);
  SmoothedRun run;
  run.start_ns = sim.start_time_ns();
  struct Solution {  // the forward solution after an IMU sample: what is scored
    std::int64_t time_ns;
    double lat_rad, lon_rad, height_m;
    Eigen::Vector3d vel_ned_mps;
    Eigen::Quaterniond q_nb;
    bool navigating;
  };
  std::vector<sim::TruthSample> truth;  // at every IMU sample's true time
  std::vector<Solution> solutions;
  Measurement m;
  while (sim.next(m)) {
    engine.process(m);
    if (kind_of(m) != MeasurementKind::kImu) continue;
    const NavSolution& s = engine.solution();
    truth.push_back(sim.truth());
    solutions.push_back({s.header.time_ns, s.lat_rad, s.lon_rad, s.height_m, s.vel_ned_mps, s.q_nb,
                         s.mode == NavMode::kNavigation || s.mode == NavMode::kDeadReckoning});
  }
  std::size_t j = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Solution& s = solutions[i];
    while (j + 1 < truth.size() && truth[j].time_ns < s.time_ns) ++j;
    ForwardEpoch ep;
    ep.truth = truth[j].time_ns == s.time_ns ? truth[j] : truth[i];
    ep.error = error_against(ep.truth, s.lat_rad, s.lon_rad, s.height_m, s.vel_ned_mps, s.q_nb);
    ep.navigating = s.navigating;
    run.forward.push_back(ep);
  }
  recorder.close(engine.core());
  run.stats = engine.stats();
  run.record_bytes = recorder.bytes();
  run.replaced = recorder.replaced();
  std::size_t k = 0;
  run.smoother = smooth(recorder, [&](const SmoothedSample& s) {
    while (k < run.forward.size() && run.forward[k].truth.time_ns < s.x.time_ns) ++k;
    if (k == run.forward.size() || run.forward[k].truth.time_ns != s.x.time_ns) return;
    const sim::TruthSample& t = run.forward[k].truth;
    on_smoothed(s, t, error_against(t, s.x.lat_rad, s.x.lon_rad, s.x.height_m, s.x.vel_ned_mps, s.x.q_nb));
  });
  return run;
}

}  // namespace navfuse::filter::test

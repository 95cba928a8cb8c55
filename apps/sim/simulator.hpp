// The simulator: truth trajectory plus IMU, GNSS and wheel models, producing one stream of core
// Measurements in DELIVERY order (what a device's port would deliver), plus truth at the IMU rate.
//
// Timing:
//  - IMU samples are stamped at start + k / rate, k = 1..N (increments cover the preceding
//    interval) and delivered at their stamp.
//  - GNSS and wheel measurements are taken on their own GPS-time grids (multiples of 1/rate) and
//    delivered `latency_s` after their stamp; header.time_ns is always the true measurement time.
//  - Ordering is by delivery time; equal delivery times keep generation order, so the older
//    measurement goes first: without latency the IMU sample at t precedes the GNSS fix stamped at
//    t, while a fix delayed to arrive at t precedes the IMU sample at t. Within one epoch the
//    order is GNSS position, velocity, heading, then vehicle speed, wheel speeds. Measurements
//    still in flight when the trajectory ends are not delivered.
//
// Usage, streaming (no heap allocation per IMU sample once running):
//   Simulator sim(make_scenario("drive_outage"));
//   Measurement m;
//   while (sim.next(m)) { if (kind_of(m) == MeasurementKind::kImu) use(sim.truth()); ... }
// or batch:
//   SimulationOutput out = simulate(scenario);
#pragma once

#include <cstdint>
#include <vector>

#include "apps/sim/gnss_model.hpp"
#include "apps/sim/imu_model.hpp"
#include "apps/sim/scenario.hpp"
#include "apps/sim/trajectory.hpp"
#include "apps/sim/wheel_model.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::sim {

class Simulator {
 public:
  // Throws std::invalid_argument for an inconsistent scenario (non-positive rates, periods that
  // are not whole nanoseconds, bad segments).
  explicit Simulator(const Scenario& scenario);

  // Next measurement in delivery order; false when the scenario has ended.
  bool next(Measurement& out);
  // Delivery time (GPS ns) of the measurement last returned by next().
  std::int64_t delivery_time_ns() const { return last_delivery_ns_; }
  // Truth at the time of the most recent IMU sample generated: after next() returns an ImuSample,
  // this is the truth at its header.time_ns (IMU samples have no latency).
  const TruthSample& truth() const { return imu_truth_; }
  // Truth at the scenario start (before the first IMU sample).
  const TruthSample& initial_truth() const { return initial_truth_; }

  const Scenario& scenario() const { return scenario_; }
  const Trajectory& trajectory() const { return trajectory_; }
  const ImuModel& imu() const { return imu_; }
  std::int64_t start_time_ns() const { return scenario_.start_time_ns; }
  std::int64_t end_time_ns() const { return end_time_ns_; }
  std::int64_t imu_sample_count() const { return imu_count_; }  // total over the scenario

 private:
  struct Pending {
    std::int64_t delivery_ns = 0;
    std::uint64_t order = 0;  // generation order: ties keep it
    Measurement measurement;
  };
  void step();  // generates IMU sample k and every other measurement stamped in its interval
  void push(std::int64_t delivery_ns);  // queues scratch_
  void sensor_events(std::int64_t t_end_ns);
  void gnss_events(GnssModel& gnss, std::int64_t& next_ns, std::int64_t t_end_ns);
  TruthSample truth_in_interval(std::int64_t time_ns) const;
  double seconds_since_start(std::int64_t time_ns) const;

  Scenario scenario_;
  Trajectory trajectory_;
  ImuModel imu_;
  GnssModel gnss_;
  GnssModel second_gnss_;
  WheelModel wheel_;
  std::int64_t end_time_ns_ = 0;
  std::int64_t imu_count_ = 0;
  std::int64_t k_ = 0;  // IMU samples generated so far
  std::int64_t substep_ns_ = 0;
  std::int64_t next_gnss_ns_ = 0;   // next epoch on the GNSS grid
  std::int64_t next_second_gnss_ns_ = 0;
  std::int64_t next_wheel_ns_ = 0;  // next epoch on the wheel grid
  std::vector<TruthSample> nodes_;  // substep truth nodes of the current interval
  TruthSample initial_truth_;
  TruthSample imu_truth_;
  std::vector<Pending> pending_;  // sorted by (delivery_ns, order), capacity reserved up front
  std::size_t pending_head_ = 0;
  std::uint64_t order_ = 0;
  std::int64_t last_delivery_ns_ = 0;
  // Scratch measurement reused for every output (no allocation in the loop).
  Measurement scratch_;
  GnssPosition gnss_pos_;
  GnssVelocity gnss_vel_;
  GnssHeading gnss_heading_;
};

struct SimulationOutput {
  std::vector<Measurement> measurements;      // delivery order
  std::vector<std::int64_t> delivery_time_ns;  // parallel to `measurements`
  std::vector<TruthSample> truth;             // one per IMU sample, same times
  TruthSample initial_truth;                  // at the scenario start
};
SimulationOutput simulate(const Scenario& scenario);

// The truth sample at `time_ns` (exact match) or, between samples, the latest one before it;
// nullptr before the first sample. `truth` must be sorted by time (as simulate() returns it).
const TruthSample* find_truth(const std::vector<TruthSample>& truth, std::int64_t time_ns);

}  // namespace navfuse::sim

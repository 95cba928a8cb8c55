// The one fusion loop body of navfuse: every measurement `replay`, `bench` and `run` hand to the
// filter goes through FusionRunner::offer(), whatever its source (a merged log, a live queue).
//
//   offered measurement -> decoded count -> time-base gate -> IMU time guard -> filter
//     -> (IMU epoch?) -> OutputEpoch
//
// The runner owns the time-base gate (apps/fusion/time_base_gate.hpp), the guard against a lone
// wild IMU timestamp (apps/fusion/imu_time_guard.hpp), the per-kind counts, the
// engine, the detection of a new IMU epoch, the output-rate decision (output.rate_hz) and the
// run statistics of the Summary. What a command does with the stream it sees through a
// FusionObserver: replay writes poses and scores truth, bench records the device and navfuse
// tracks, run posts epochs to its output links and LCM. None of them repeats a step of the loop.
//
// Costs per IMU sample: the solution is filled only when an observer asks for it (every epoch,
// or only at pose epochs), so a replay without outputs runs the filter alone.
#pragma once

#include <cstdint>
#include <optional>

#include "apps/common/summary.hpp"
#include "apps/fusion/measurement_counts.hpp"
#include "apps/fusion/output_epoch.hpp"
#include "apps/fusion/gnss_outage_plan.hpp"
#include "apps/fusion/imu_time_guard.hpp"
#include "apps/fusion/time_base_gate.hpp"
#include "apps/output/output_rate.hpp"
#include "core/measurements/measurements.hpp"
#include "filter/engine.hpp"

namespace navfuse::apps {

class FusionObserver {
 public:
  virtual ~FusionObserver() = default;
  // Every offered measurement, before the time-base gate (bench keeps device solutions whatever
  // their clock, to report a mismatch rather than silently drop them).
  virtual void on_offered(const Measurement&) {}
  // A measurement that passed the gate, just before the filter takes it.
  virtual void on_fused(const Measurement&) {}
  // The filter advanced by one IMU sample. epoch.solution is filled as Options::solutions says.
  virtual void on_epoch(const OutputEpoch& /*epoch*/, const filter::Engine& /*engine*/) {}
  // Solutions::kDeferred: where the runner assembles the next epoch it hands to on_epoch(). An
  // observer that queues epochs returns its queue's next slot, so that the ~1 kB of solution
  // inputs is captured in place rather than copied once more per IMU sample. nullptr: the
  // runner's own epoch. Only the fields the runner sets for kDeferred are written.
  virtual OutputEpoch* epoch_slot() { return nullptr; }
  // A log is used up (replay, bench): still inside the timed part of the run, so work an
  // observer handed to another thread is finished here and counted in the rate.
  virtual void on_finished() {}
};

class FusionRunner {
 public:
  // Which epochs carry a filled solution (filling it costs about as much as a filter step).
  // kDeferred: every epoch, as the inputs of the solution (OutputEpoch::solution_inputs), for an
  // observer that fills it on another thread (replay's PoseOutputThread).
  enum class Solutions { kNone, kPoses, kEvery, kDeferred };
  struct Options {
    double output_rate_hz = 0.0;  // output.rate_hz: 0 = a pose at every IMU epoch
    Solutions solutions = Solutions::kEvery;
    std::optional<GnssOutagePlan> gnss_outages;  // replay --gnss-outage: GNSS withheld in windows
  };

  FusionRunner(const filter::FilterOptions& filter_options, const Options& options, FusionObserver& observer);

  // One measurement, from any input. `arrival_ns`: host time its bytes arrived (run), or 0.
  void offer(const Measurement& m, std::int64_t arrival_ns = 0);
  // The input ended: an IMU sample still held by the time guard is rejected (see
  // imu_time_guard.hpp). Call once before fill_summary().
  void finish();

  filter::Engine& engine() { return engine_; }
  const filter::Engine& engine() const { return engine_; }

  std::uint64_t imu_samples() const { return imu_samples_; }                // given to the filter
  const std::optional<MeasurementHeader>& first_imu() const { return first_imu_; }
  std::int64_t last_imu_ns() const { return last_imu_ns_; }
  std::uint64_t poses() const { return poses_; }                            // pose epochs
  std::uint64_t gated_total() const { return gated_total_; }                // kept from the filter

  // Measurement counts (decoded / used / rejected by reason) and run statistics over `wall_s`.
  void fill_summary(Summary& summary, double wall_s) const;

 private:
  void offer_imu(const Measurement& m, std::int64_t arrival_ns);
  void fuse_imu(const Measurement& m, std::int64_t arrival_ns);
  void reject_held_imu();
  void after_imu(const ImuSample& s, std::int64_t arrival_ns);

  filter::Engine engine_;
  FusionObserver& observer_;
  Solutions solutions_;
  std::optional<GnssOutagePlan> outages_;
  TimeBaseGate gate_;
  ImuTimeGuard imu_guard_;
  Measurement held_imu_;  // held by imu_guard_ until the next sample tells what it was
  std::int64_t held_arrival_ns_ = 0;
  OutputRate rate_;
  MeasurementCounts counts_;
  OutputEpoch epoch_;
  std::uint64_t last_engine_epoch_ = 0;
  std::uint64_t gnss_at_last_pose_ = 0;
  std::uint8_t num_sats_ = 0;
  std::uint64_t imu_samples_ = 0;
  std::uint64_t poses_ = 0;
  std::uint64_t gated_total_ = 0;
  std::optional<MeasurementHeader> first_imu_;
  std::int64_t last_imu_ns_ = 0;
};

}  // namespace navfuse::apps

// navfuse::filter::Engine: the loosely-coupled GNSS/INS error-state EKF behind one small API.
//
//   FilterOptions opts = options_from_config(config);   // or defaults, then adjust
//   Engine engine(opts);
//   for (const Measurement& m : stream) {               // any kind, any order
//     engine.process(m);
//     if (is IMU) publish(engine.solution());           // current to the newest IMU sample
//   }
//   engine.stats();                                     // used / ignored / rejected by reason
//
// Behaviour:
// - IMU samples (rates or increments, sensor or vehicle frame) drive the strapdown mechanisation;
//   imu_epoch() increments once per processed sample so callers can emit a pose per sample.
//   An IMU sample not after the previous one is rejected ("time_backwards"); a gap longer than
//   FilterOptions::max_imu_gap_s restarts the filter ("time_gap").
// - Every other measurement is fused at its own timestamp. One that lies between IMU samples is
//   fused at the nearest sample with its small time offset modelled; one from the future waits
//   for the IMU to reach it; one from the past (up to max_latency_s, default 1 s) is fused by
//   restoring the state snapshot before it and re-propagating the stored IMU samples and
//   measurements (exact, not an approximation). Older ones are rejected ("too_late").
//   Odometry (the kinds whose row in measurement_kinds.hpp says FuseTime::kCovarianceGrid) waits
//   instead for the end of the covariance step its time falls in and is fused there, its time
//   shift modelled; one that arrives late but within that step needs no re-propagation.
// - Bad inputs (NaN/inf: "nan"; uncertainty <= 0 on a valid axis: "negative_std"; no valid axis
//   or impossible values: "invalid") are rejected before they reach the state. Kinds the filter
//   does not use (measurement_kinds.hpp: device solutions; magnetometer and pressure unless the
//   configuration switches them on, FilterOptions::fuses) are counted as ignored.
// - Modes follow MIP's filter states: Init -> Vertical Gyro (levelled while stationary) -> AHRS
//   (heading from dual antenna, external heading, magnetometer or FilterOptions::initial_heading_rad) -> Full
//   Navigation (position known; heading from GNSS course above 2 m/s if no other source) ->
//   Dead Reckoning after gnss_timeout_s without absolute position (kStatusGnssOutage).
//
// NavSolution fields: LLH (ellipsoidal height; undulation from EGM96 when installed), NED and
// vehicle-frame velocity, q_nb and roll/pitch/yaw, 1-sigma position (NED), velocity (NED) and
// attitude (roll, pitch, yaw) stds, IMU biases and their stds in the IMU *sensor* frame (as MIP
// 0x82,0x06/07 report them), bias-compensated angular rate and gravity-free acceleration in the
// vehicle frame, gravity in NED, mode, gnss_fix (the fix type of the GNSS position in use, kNone
// when none is), status_flags (kStatus* bits) and header.valid (kValid* bits by mode).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"
#include "filter/filter_options.hpp"
#include "filter/filter_stats.hpp"
#include "filter/imu_input.hpp"
#include "filter/measurement_kinds.hpp"
#include "filter/ring_buffer.hpp"
#include "filter/solution.hpp"

namespace navfuse::filter {

class Engine {
 public:
  // reset() mask bits.
  static constexpr std::uint32_t kResetFilter = 1u << 0;    // everything: back to Init
  static constexpr std::uint32_t kResetHeading = 1u << 1;   // heading unknown: re-align
  static constexpr std::uint32_t kResetBiases = 1u << 2;    // IMU biases to zero, initial std
  static constexpr std::uint32_t kResetPosition = 1u << 3;  // position unknown: next fix places
  static constexpr std::uint32_t kResetAll = 0xFFFFFFFFu;

  explicit Engine(const FilterOptions& options);

  void process(const Measurement& m);
  // Whether process() fuses this kind: it has a model (measurement_kinds.hpp) and the options
  // switch it on (FilterOptions::fuses). The rest is counted as ignored.
  bool fuses(MeasurementKind kind) const { return is_fused(kind) && options_.fuses(kind); }

  const NavSolution& solution() const;
  // What solution() is computed from (filter/solution.hpp), for a caller that fills it elsewhere.
  void capture_solution(SolutionInputs& in) const;
  bool solution_valid() const;
  std::uint64_t imu_epoch() const { return imu_epoch_; }
  const FilterStats& stats() const;
  // Measurements of `kind` used so far (cheap: stats() copies the whole table).
  std::uint64_t used(MeasurementKind kind) const { return stats_.of(kind).used; }
  // Measurements of `kind` held for the IMU to reach their time and not yet fused or rejected:
  // at the end of a log, what is neither used nor rejected (decoded = used + rejected + pending).
  std::uint64_t pending(MeasurementKind kind) const;
  const FilterOptions& options() const { return options_; }
  // Restarts the filter made on its own, by cause (FilterStats::resets counts commands' too):
  // an IMU gap beyond max_imu_gap_s, a diverged state.
  std::uint64_t time_gap_restarts() const {
    return stats_.of(MeasurementKind::kImu).rejected_for(RejectReason::kTimeGap);
  }
  std::uint64_t divergence_restarts() const { return core_.mode.divergences; }

  void reset(std::uint32_t mask);
  // antenna 0: primary (position/velocity), 1: secondary (dual-antenna heading baseline, and
  // where fixes of receiver_id 1 are measured).
  void set_gnss_lever_arm(const Eigen::Vector3d& lever_arm_m, int antenna = 0);
  // Sensor -> vehicle roll, pitch, yaw (rad, 3-2-1); like MIP, a new mounting restarts the filter.
  void set_mounting(const Eigen::Vector3d& rpy_rad);
  void set_wheel_lever_arm(const Eigen::Vector3d& lever_arm_m);
  // A heading for the filter to align to (MIP 0x0D,0x03, digest §6.4): taken with
  // initial_heading_std_rad once levelled while no heading is known; ignored (false) when the
  // heading is already known or magnetometer aiding is on ("ignored if magnetometer aiding is
  // supported and enabled", L8256). A filter reset forgets one not yet taken.
  bool set_initial_heading(double heading_rad);
  // The non-holonomic (wheeled-vehicle) constraint on or off (MIP 0x0D,0x63).
  void set_nonholonomic(bool on) { options_.land_vehicle = on; }
  // Aiding of `kind` on, as the configuration has it, or off: then counted as ignored (MIP
  // 0x0D,0x50). The IMU is not aiding and stays on.
  void set_aiding(MeasurementKind kind, bool on);
  std::vector<NavMode> modes_reached() const;

  // Records the forward pass for the smoother from now on (filter/smoother/forward_record.hpp);
  // nullptr stops. The recorder must outlive the recording.
  void record_to(ForwardRecorder* recorder) { core_.record.sink = recorder; }
  // Called once per aiding measurement when its outcome is first known (not again when a late
  // measurement re-propagates it): `--innovations-csv`.
  using InnovationSink = void (*)(void* context, const Measurement& m, const FuseResult& result);
  void set_innovation_sink(InnovationSink sink, void* context) {
    innovation_sink_ = sink;
    innovation_context_ = context;
  }

  // Internals for tests and tools: full covariance and nominal state.
  const FilterCore& core() const { return core_; }

 private:
  struct ImuRecord {
    ImuIncrement increment;
    std::int64_t horizon_ns = 0;  // measurements before this are fused at or before this sample
    std::uint64_t seq = 0;
  };
  struct Checkpoint {
    FilterCore core;
    std::int64_t horizon_ns = 0;
    std::uint64_t seq = 0;
    std::uint64_t fused_order = 0;  // fused_order_ when the snapshot was taken
  };
  struct Entry {
    Measurement m;
    std::int64_t time_ns = 0;
    // When it was fused, in the order of fusion (fused_order_), 0 while not: the snapshots hold
    // exactly the entries fused before them, whatever their timestamps.
    std::uint64_t fused_order = 0;
    bool counted = false;
    bool applied() const { return fused_order != 0; }
  };

  void dispatch(MeasurementKind kind, const Measurement& m);
  void process_imu(const ImuSample& s);
  void process_aiding(const Measurement& m);
  void run_increment(const ImuRecord& record);
  void fuse_due(std::int64_t horizon_ns);
  void fuse_entry(Entry& e);
  // Whether `e` waits for the covariance grid (FuseTime::kCovarianceGrid) and the covariance is
  // not at it now.
  bool waits_for_grid(const Entry& e) const;
  void maybe_checkpoint(const ImuRecord& record);
  void replay_from(std::int64_t time_ns);
  void forget_history();
  // The held aiding and the snapshots (and what keeps track of them) are gone: nothing from before
  // is fused again or re-propagated into what comes.
  void drop_snapshots_and_entries();
  void take_initial_heading();
  void count(MeasurementKind kind, const FuseResult& r);
  void fill_solution() const;

  std::optional<double> initial_heading_rad_;  // set_initial_heading(), not yet taken
  FilterOptions options_;
  FilterCore core_;
  ImuInput imu_input_;
  TimeSource imu_time_source_ = TimeSource::kUnknown;
  std::uint64_t imu_epoch_ = 0;
  std::uint64_t imu_seq_ = 0;
  std::int64_t latest_horizon_ns_ = INT64_MIN;
  std::int64_t previous_horizon_ns_ = INT64_MIN;
  std::int64_t last_checkpoint_ns_ = INT64_MIN;
  std::uint64_t fused_order_ = 0;
  // The oldest entry before previous_horizon_ns_ not yet fused (waiting for the covariance grid,
  // or reset by a re-propagation); INT64_MAX when there is none. fuse_due() scans from it.
  std::int64_t unfused_from_ns_ = INT64_MAX;

  RingBuffer<ImuRecord> imu_history_;
  RingBuffer<Checkpoint> checkpoints_;
  std::vector<Entry> entries_;  // aiding measurements by time; capacity reserved once

  FilterStats stats_;
  mutable FilterStats stats_view_;
  InnovationSink innovation_sink_ = nullptr;
  void* innovation_context_ = nullptr;
  mutable SolutionInputs solution_inputs_;
  mutable NavSolution solution_;
  mutable bool solution_dirty_ = true;
};

}  // namespace navfuse::filter

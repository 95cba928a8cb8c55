// A record of the forward filter pass, for the RTS smoother (filter/smoother/rts_smoother.hpp).
//
// What is written, in the order the filter does it (FilterCore calls the record_* hooks below
// only when a ForwardRecorder is attached, Engine::record_to):
//   kIntervalStart  before the first strapdown step of a covariance interval: the nominal state
//                   x+ and covariance P+ the interval starts from (after every update, reset and
//                   variance floor since the last propagation: the smoother's posterior).
//   kImu            after every strapdown step: the nominal state at the sample, the compensated
//                   rate and force, and the forward solution's mode / fix / flag words.
//   kPropagation    when the covariance is propagated over the interval: the nominal state x-
//                   (the strapdown of x+), the transition matrix Phi = I + F T + (F T)^2 / 2 of
//                   the step (process_model.hpp; formed here, only when recording) and the
//                   propagated P- (the smoother's prior).
//                   A covariance transformed outside an update (re-inflation) is written as a
//                   zero-length step: kIntervalStart with P before the change (and whether the
//                   filter was dead reckoning then), kPropagation with the same state, the
//                   transformation as Phi and P after it. Left inside a node
//                   (between its kPropagation and the next kIntervalStart), the smoother would
//                   take the wider posterior for an update's and its gain would use the narrower
//                   prior: on a wrong installation that carried back corrections of metres.
//   kUpdate         every accepted measurement update: state before and after, residual, H, R,
//                   the correction dx and the NIS (diagnostics and tests; the smoother itself
//                   needs only the next kIntervalStart, which carries P after every update,
//                   variance floor and reset since the last kPropagation or covariance change).
//   kRestart        the filter restarted (divergence, time gap, reset): nothing is smoothed across.
//   kBreak          the nominal state moved inside an interval without an update (alignment,
//                   re-anchoring): not smoothed across either.
//   kClose          the filter's final state and covariance (written by close()).
//
// Late measurements: each FilterCore carries the index of its next record (RecordHook). When
// the Engine re-propagates from a snapshot, the snapshot's index comes back, and the first record
// written at an index already used truncates the record there: a re-propagated span replaces what
// it recomputes, so the record is always the history of the final forward solution.
//
// Storage: an anonymous temporary file (std::tmpfile, deleted on close), written sequentially and
// read by record index; memory holds one 9-byte index entry per record. Covariances are stored as
// the upper triangle of the active block, Phi as its rows with dynamics (the rest are identity):
// about 2 kB per covariance interval and 0.3 kB per IMU sample for the 16-state filter.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"
#include "filter/ekf.hpp"
#include "filter/filter_core.hpp"
#include "filter/nav_state.hpp"
#include "filter/process_model.hpp"

namespace navfuse::filter {

enum class RecordType : std::uint8_t {
  kIntervalStart = 1,
  kImu = 2,
  kPropagation = 3,
  kUpdate = 4,
  kRestart = 5,
  kBreak = 6,
  kClose = 7,
};

// One record read back. Only the fields of its type are meaningful.
struct ForwardRecordEntry {
  RecordType type = RecordType::kRestart;
  std::int64_t time_ns = 0;
  int n = 0;                       // active dimension of p / phi
  NavState x;                      // interval start, IMU, propagation, close; update: after
  Covariance p = Covariance::Zero();    // interval start, propagation (P-), close
  Covariance phi = Covariance::Identity();  // propagation
  bool navigating = false;         // interval start, close: levelled, heading and position known
  // interval start of a covariance change: a re-inflation while the filter was dead reckoning
  // (no absolute position for longer than gnss_timeout_s: the fixes ending an outage were gated)
  bool inflation_after_outage = false;
  // kImu
  Eigen::Vector3d rate_b_rps = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_b_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d gravity_ned_mps2 = Eigen::Vector3d::Zero();
  NavMode mode = NavMode::kInvalid;
  GnssFixType gnss_fix = GnssFixType::kNone;
  std::uint32_t valid = 0;         // NavSolution::header.valid of the forward solution
  std::uint32_t status_flags = 0;  // NavSolution::status_flags of the forward solution
  // kUpdate
  NavState x_before;
  Observation obs;
  StateVector dx = StateVector::Zero();
  double nis = 0.0;
};

class ForwardRecorder {
 public:
  // Opens the temporary file: std::runtime_error when none can be created.
  ForwardRecorder();
  ~ForwardRecorder();
  ForwardRecorder(const ForwardRecorder&) = delete;
  ForwardRecorder& operator=(const ForwardRecorder&) = delete;

  // Appends the record numbered `index` (bytes of `payload` after the type byte); an index
  // already written first truncates the record there (see the header comment).
  void write(std::uint64_t index, RecordType type, const std::vector<unsigned char>& payload);
  // The final state: a kClose record after everything `core` wrote.
  void close(const FilterCore& core);

  std::size_t size() const { return offsets_.size(); }
  RecordType type(std::size_t i) const { return types_[i]; }
  // Reads record `i`. False, with error() set, on an I/O error.
  bool read(std::size_t i, ForwardRecordEntry& out);

  std::uint64_t bytes() const { return end_; }            // on disk, records in use
  std::uint64_t replaced() const { return replaced_; }    // records dropped by re-propagation
  const std::string& error() const { return error_; }     // first I/O error, empty when none

 private:
  void fail(const std::string& what);

  std::FILE* file_ = nullptr;
  std::vector<std::uint64_t> offsets_;
  std::vector<RecordType> types_;
  std::uint64_t end_ = 0;       // logical end of the record
  std::uint64_t position_ = 0;  // where the write position is (a seek only after truncation)
  bool unflushed_ = false;      // written bytes may still be in stdio's buffer
  std::uint64_t replaced_ = 0;
  std::vector<unsigned char> buffer_;
  std::string error_;
};

// Hooks FilterCore calls when core.record.sink is set (filter_core.cpp).
// Before each strapdown step: kIntervalStart at an interval's first step, else kBreak if the
// state moved since the previous step.
void record_step_start(FilterCore& core);
// After each strapdown step.
void record_imu(FilterCore& core, const FilterOptions& o);
// After the covariance was propagated over core.step (before the step is cleared).
void record_propagation(FilterCore& core);
// After the covariance was transformed outside an update and a propagation, P = Phi before Phi^T
// with the state unchanged (re-inflation, innovation_adaptation.cpp): a zero-length step whose
// transition is `phi_rows` (the rows with dynamics; identity below them) and no process noise.
// `after_outage`: the filter was dead reckoning when it re-inflated (the smoother's gain through
// such a change is I, rts_smoother.hpp).
void record_covariance_change(FilterCore& core, const Covariance& before, const SystemRows& phi_rows,
                              bool after_outage);
// After an accepted update that moved the state from `before`.
void record_update(FilterCore& core, const NavState& before, const Observation& obs, const UpdateResult& r);
// Before the filter restarts.
void record_restart(FilterCore& core);

}  // namespace navfuse::filter

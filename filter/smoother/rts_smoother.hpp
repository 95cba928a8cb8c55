// Rauch-Tung-Striebel fixed-interval smoother over a forward record (forward_record.hpp), in
// error-state form (Rauch, Tung & Striebel 1965; the error-state form as in Groves 2nd ed.
// §3.4.2 and Shin 2005 §4.4).
//
// The record's covariance nodes k = 0..N are the covariance propagations: the posterior x+_k,
// P+_k (kIntervalStart) starts an interval, whose strapdown gives the prior x-_{k+1} (the error
// state's mean is zero there by construction) with P-_{k+1} = Phi P+_k Phi^T + Q (kPropagation).
// Going backwards from the last node, with the smoothed state xs_{k+1} and Ps_{k+1}:
//   e_{k+1}  = xs_{k+1} relative to x-_{k+1}     (state_difference: NED metres, attitude phi)
//   C_k      = P+_k Phi^T (P-_{k+1})^-1
//   d_k      = C_k e_{k+1}                       (the smoothed error at k)
//   xs_k     = x+_k corrected by d_k             (inject_error: the attitude by composition)
//   Ps_k     = P+_k + C_k (Ps_{k+1} - P-_{k+1}) C_k^T
// States whose prior variance is zero (inactive states, the vertical-gyro heading) have no
// cross-covariance through the step and get no gain. Between two nodes the nominal state is
// pure strapdown, so the correction at an IMU sample inside an interval is taken linearly
// between d_k and e_{k+1} (and the covariance between Ps_k and Ps_{k+1}): the error state changes
// by Phi over at most one covariance step (<= 50 ms), a first-order change.
//
// A covariance re-inflation is recorded as a zero-length interval with Phi = D (forward_record.hpp)
// and no noise: a node like any other, whose gain P+ D (D P+ D)^-1 = D^-1 shrinks the position
// and velocity correction carried back through it by the inflation factor, while fixes arrive
// (there a jump is the installation's). One the filter made while dead reckoning (recorded as
// after an outage, innovation_adaptation.cpp) passes the correction unchanged (gain I): the fix
// that ended the outage then corrects the outage's end.
//
// Restarts and breaks (forward_record.hpp) end a segment: each is smoothed on its own, and its
// last node keeps the filtered state. Only intervals that start navigating (levelled, heading and
// position known) are smoothed: before that the filter's prior is no distribution around the
// truth (relative heading, unplaced position). IMU samples outside any smoothed interval (before
// navigation, after the last node) are not reported.
//
// Memory: the backward pass keeps, per interval, the two corrections and the covariance blocks
// the outputs use (~0.9 kB); the record itself stays on disk.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "core/measurements/measurements.hpp"
#include "filter/filter_options.hpp"
#include "filter/nav_state.hpp"
#include "filter/smoother/forward_record.hpp"

namespace navfuse::filter {

struct SmoothedSample {
  NavState x;     // smoothed nominal state at the IMU sample
  Covariance p;   // smoothed covariance: position, velocity, attitude and bias blocks; 0 elsewhere
  const ForwardRecordEntry& forward;  // the sample's kImu record: the forward state and its words
};

struct SmootherStats {
  std::uint64_t intervals = 0;         // covariance intervals smoothed
  std::uint64_t segments = 0;          // runs between restarts / breaks with at least one interval
  std::uint64_t imu_samples = 0;       // kImu records read
  std::uint64_t smoothed_samples = 0;  // reported
  std::uint64_t singular = 0;          // intervals whose prior could not be inverted (not smoothed)
  std::string error;                   // I/O error reading the record, empty when none
};

// Smooths `record` and calls `on_sample` for every smoothed IMU sample, in time order.
// `progress` (optional) sees the fraction done, 0..1, now and then.
SmootherStats smooth(ForwardRecorder& record, const std::function<void(const SmoothedSample&)>& on_sample,
                     const std::function<void(double)>& progress = {});

// The smoothed sample as a NavSolution: mode kSmoothed where the forward filter was navigating
// (its own mode before), the forward fix in use, validity and status words, the smoothed state and
// its stds.
NavSolution smoothed_solution(const SmoothedSample& sample, const FilterOptions& o, TimeSource time_source);

}  // namespace navfuse::filter

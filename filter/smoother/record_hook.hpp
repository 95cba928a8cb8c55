// The forward-pass recording hook carried inside FilterCore (filter/smoother/forward_record.hpp
// writes through it). It is part of the copyable filter state on purpose: the Engine's
// re-propagation of a late measurement restores a FilterCore snapshot, and with it
// `next_index`, so the records the re-propagated span recomputes are written over the ones it
// replaces (ForwardRecorder truncates at the first index it sees again).
#pragma once

#include <cstdint>

#include "filter/nav_state.hpp"

namespace navfuse::filter {

class ForwardRecorder;

struct RecordHook {
  ForwardRecorder* sink = nullptr;  // null: not recording (the forward filter pays one test)
  std::uint64_t next_index = 0;     // index of the next record this state writes
  // The nominal state after the last strapdown step: a state that differs from it at the next
  // step inside a covariance interval was moved by something other than a recorded update
  // (alignment, re-anchoring), which the smoother must not smooth across.
  NavState after_strapdown;
};

}  // namespace navfuse::filter

// Exponential backoff between attempts to re-open a lost link, so a missing device or a dead
// peer costs one system call per interval rather than a busy loop, while a brief glitch is
// retried quickly. Delay: initial, 2x, 4x, ... capped at max; reset by a success.
#pragma once

#include <algorithm>

#include "core/io/unique_fd.hpp"

namespace navfuse::io {

class ReconnectBackoff {
 public:
  ReconnectBackoff(int initial_ms, int max_ms)
      : initial_ms_(std::max(initial_ms, 1)), max_ms_(std::max(max_ms, initial_ms_)), delay_ms_(initial_ms_) {}

  // An attempt failed (or the link was lost): the next one is due after the current delay.
  void failed() {
    next_ = Deadline(delay_ms_).when();
    delay_ms_ = std::min(delay_ms_ * 2, max_ms_);
  }
  void succeeded() { delay_ms_ = initial_ms_; }
  bool due() const { return Deadline::Clock::now() >= next_; }
  Deadline::Clock::time_point next_attempt() const { return next_; }

 private:
  int initial_ms_;
  int max_ms_;
  int delay_ms_;
  Deadline::Clock::time_point next_{};
};

}  // namespace navfuse::io

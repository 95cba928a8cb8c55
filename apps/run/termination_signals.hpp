// SIGINT / SIGTERM for the nav process. They are blocked in every thread (the mask is inherited
// by threads created afterwards) and collected synchronously by the main thread with
// sigtimedwait(2), so that shutdown runs as ordinary code rather than in a signal handler, where
// almost nothing may be called (POSIX signal-safety(7)).
#pragma once

#include <signal.h>

namespace navfuse::apps {

class TerminationSignals {
 public:
  // Blocks SIGINT and SIGTERM in the calling thread; create before starting any thread.
  TerminationSignals();
  // Restores the previous mask (signals still pending are delivered then, as usual).
  ~TerminationSignals();
  TerminationSignals(const TerminationSignals&) = delete;
  TerminationSignals& operator=(const TerminationSignals&) = delete;

  // Waits up to timeout_ms; returns the signal number received, or 0.
  int wait(int timeout_ms);

 private:
  sigset_t set_{};
  sigset_t previous_{};
};

}  // namespace navfuse::apps

// Ctrl-C (SIGINT) and SIGTERM for the batch commands (replay): instead of ending the process
// at once, which left no summary and cut output files (issue 15.3), the signal only sets a flag
// that the processing loop polls; the command then stops reading, finishes and commits what it
// has, prints its summary and exits non-zero (128 + signal, as a shell reports it).
// (The live `run` collects its signals synchronously instead: apps/run/termination_signals.hpp.)
#pragma once

#include <signal.h>

#include <atomic>

namespace navfuse::apps {

class InterruptSignals {
 public:
  // Installs the handlers; the previous ones come back on destruction. One instance at a time.
  InterruptSignals();
  ~InterruptSignals();
  InterruptSignals(const InterruptSignals&) = delete;
  InterruptSignals& operator=(const InterruptSignals&) = delete;

  // The signal received (SIGINT, SIGTERM), 0 while none. Lock-free: the handler writes it.
  static const std::atomic<int>& received();

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

}  // namespace navfuse::apps

// Ctrl-C (SIGINT) and SIGTERM for the batch commands (replay, bench, decode, sim): instead of
// ending the process at once, which left no summary and cut output files (issue 15.3), the signal
// only sets a flag that the processing loop polls; the command then stops reading, finishes and
// commits what it has, prints its summary and exits non-zero (128 + signal, as a shell reports
// it). A write blocked on a stalled pipe or FIFO would never return to the loop, so the handler
// also makes wake_fd() readable: OutputFile waits on it next to the output (poll(2)) and gives
// up on a reader that takes nothing more once a signal came.
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
  // A descriptor that becomes (and stays) readable when a signal is received; -1 while no
  // handlers are installed.
  static int wake_fd();

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

// Exit status of a command stopped by `signal_number` (130 for SIGINT, 143 for SIGTERM).
inline int interrupted_exit_code(int signal_number) { return 128 + signal_number; }

}  // namespace navfuse::apps

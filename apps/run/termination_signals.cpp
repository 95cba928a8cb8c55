#include "apps/run/termination_signals.hpp"

#include <pthread.h>

#include <cerrno>
#include <ctime>

namespace navfuse::apps {

TerminationSignals::TerminationSignals() {
  sigemptyset(&set_);
  sigaddset(&set_, SIGINT);
  sigaddset(&set_, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set_, &previous_);
}

TerminationSignals::~TerminationSignals() {
  // Consume a signal that arrived during shutdown: it asked for what has just been done, and
  // unblocking it now would kill the process at the last moment.
  const timespec zero{0, 0};
  while (sigtimedwait(&set_, nullptr, &zero) > 0) {
  }
  pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

int TerminationSignals::wait(int timeout_ms) {
  const timespec timeout{timeout_ms / 1000, static_cast<long>(timeout_ms % 1000) * 1'000'000L};
  const int sig = sigtimedwait(&set_, nullptr, &timeout);
  return sig > 0 ? sig : 0;  // -1: EAGAIN (timeout) or EINTR
}

}  // namespace navfuse::apps

#include "apps/common/interrupt_signals.hpp"

#include <fcntl.h>
#include <unistd.h>

namespace navfuse::apps {
namespace {

std::atomic<int> g_received{0};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler may only touch lock-free atomics");
// Self-pipe (read end, write end): write(2) is async-signal-safe, so the handler can wake poll().
int g_wake[2] = {-1, -1};

extern "C" void on_interrupt(int signal_number) {
  g_received.store(signal_number, std::memory_order_relaxed);
  if (g_wake[1] >= 0) {
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = ::write(g_wake[1], &byte, 1);  // full pipe: already readable
  }
}

}  // namespace

InterruptSignals::InterruptSignals() {
  g_received.store(0, std::memory_order_relaxed);
  if (::pipe2(g_wake, O_CLOEXEC | O_NONBLOCK) != 0) g_wake[0] = g_wake[1] = -1;
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads and writes carry on; the loop notices the flag
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
}

InterruptSignals::~InterruptSignals() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
  for (int& fd : g_wake) {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
}

const std::atomic<int>& InterruptSignals::received() { return g_received; }

int InterruptSignals::wake_fd() { return g_wake[0]; }

}  // namespace navfuse::apps

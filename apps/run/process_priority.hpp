// What a nav process on a loaded companion computer asks of the kernel, when told to
// (`navfuse run --rt-priority PRIO --lock-memory`): SCHED_FIFO at PRIO, so that a compile or a
// logger cannot delay the filter behind the IMU, and every page locked in RAM (mlockall), so that
// no page fault stalls it. Each request is tried before the threads start (they inherit the
// policy) and its outcome reported on stderr: granted, or refused with the reason and what would
// grant it (root, CAP_SYS_NICE / CAP_IPC_LOCK, or the RLIMIT_RTPRIO / RLIMIT_MEMLOCK limits that
// the installed systemd unit sets). A refusal is not an error: the process runs on without.
#pragma once

#include <string>
#include <vector>

namespace navfuse::apps {

struct PriorityRequest {
  int rt_priority = 0;       // SCHED_FIFO priority 1..99; 0: not asked
  bool lock_memory = false;  // mlockall(MCL_CURRENT | MCL_FUTURE)
};

struct PriorityOutcome {
  bool realtime = false;     // SCHED_FIFO in effect
  bool memory_locked = false;
  std::vector<std::string> report;  // one line per request, for the log
};

PriorityOutcome apply_priority(const PriorityRequest& request);

}  // namespace navfuse::apps

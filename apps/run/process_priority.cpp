#include "apps/run/process_priority.hpp"

#include <sched.h>
#include <sys/mman.h>
#include <sys/resource.h>

#include <cerrno>
#include <cstring>

namespace navfuse::apps {
namespace {

std::string limit_text(int resource) {
  rlimit limit{};
  if (::getrlimit(resource, &limit) != 0) return "unknown";
  return limit.rlim_cur == RLIM_INFINITY ? "unlimited" : std::to_string(limit.rlim_cur);
}

}  // namespace

PriorityOutcome apply_priority(const PriorityRequest& request) {
  PriorityOutcome out;
  if (request.rt_priority > 0) {
    sched_param param{};
    param.sched_priority = request.rt_priority;
    if (::sched_setscheduler(0, SCHED_FIFO, &param) == 0) {
      out.realtime = true;
      out.report.push_back("scheduling: SCHED_FIFO priority " + std::to_string(request.rt_priority) + " in effect");
    } else {
      out.report.push_back("scheduling: SCHED_FIFO priority " + std::to_string(request.rt_priority) +
                    " not permitted (" + std::strerror(errno) + "; RLIMIT_RTPRIO " + limit_text(RLIMIT_RTPRIO) +
                    "): needs root, CAP_SYS_NICE or LimitRTPRIO>=" + std::to_string(request.rt_priority) +
                    "; running with normal scheduling");
    }
  }
  if (request.lock_memory) {
    if (::mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
      out.memory_locked = true;
      out.report.push_back("memory: locked in RAM (mlockall)");
    } else {
      out.report.push_back(std::string("memory: mlockall not permitted (") + std::strerror(errno) + "; RLIMIT_MEMLOCK " +
                    limit_text(RLIMIT_MEMLOCK) + " bytes): needs root, CAP_IPC_LOCK or LimitMEMLOCK=infinity; "
                    "running with pageable memory");
    }
  }
  return out;
}

}  // namespace navfuse::apps

#include "apps/run/run_log.hpp"

#include <iostream>
#include <mutex>

namespace navfuse::apps {

void log_event(std::string_view message) {
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  std::cerr << "navfuse run: " << message << '\n';
}

}  // namespace navfuse::apps

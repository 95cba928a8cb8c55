#include "apps/bench/report_renderer.hpp"

#include <cstdlib>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "apps/common/command_error.hpp"

extern char** environ;

namespace navfuse::apps::bench {
namespace {

std::string python_interpreter() {
  if (const char* env = std::getenv("NAVFUSE_PYTHON"); env != nullptr && *env != '\0') return env;
  if (access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return "python3";
}

}  // namespace

void render_report_html(const std::string& dir) {
  const std::string python = python_interpreter();
  // The script goes in as an argument (-c), not a temporary file: nothing to clean up.
  std::vector<std::string> args = {python, "-c", report_script(), dir};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0) {
    throw CommandError("report.html not written: cannot run '" + python +
                       "' (install python3-matplotlib: scripts/install-deps.sh, or set NAVFUSE_PYTHON)");
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw CommandError("report.html not written: the report script failed under '" + python +
                       "' (see above; it needs python3-matplotlib: scripts/install-deps.sh)");
  }
}

}  // namespace navfuse::apps::bench

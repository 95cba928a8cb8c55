// Runs the real `navfuse` binary from a test: arguments as given, stdout and stderr to a file the
// test reads, and bounded waits for its exit (a test must never hang on a child).
#pragma once

#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

namespace navfuse::test {

class ChildProcess {
 public:
  // Starts `argv[0]` with `argv`; output (stdout and stderr) goes to `log_path`.
  ChildProcess(const std::vector<std::string>& argv, const std::string& log_path);
  // A child still running is killed (SIGKILL) and reaped.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool started() const { return pid_ > 0; }
  pid_t pid() const { return pid_; }
  void send(int signal) const;
  // The exit code once the child has exited within timeout_ms; nullopt while it runs. A child
  // killed by a signal reports 128 + the signal number, as a shell does.
  std::optional<int> wait_exit(int timeout_ms);
  // The child's output so far.
  std::string output() const;
  // Waits up to timeout_ms for `text` to appear in the output.
  bool wait_for_output(const std::string& text, int timeout_ms) const;

 private:
  pid_t pid_ = -1;
  std::string log_path_;
  std::optional<int> exit_code_;
};

// Runs to completion (bounded) and returns {exit code, output}; exit code -1 on timeout.
struct RunResult {
  int exit_code = -1;
  std::string output;
};
RunResult run_to_exit(const std::vector<std::string>& argv, const std::string& log_path, int timeout_ms = 10000);

std::string read_text_file(const std::string& path);

}  // namespace navfuse::test

// `navfuse run --rt-priority PRIO --lock-memory`: what the process reports about SCHED_FIFO and
// mlockall is what the kernel shows for it (/proc/PID/stat policy, /proc/PID/status VmLck),
// whether the requests were granted (root, or the limits the systemd unit sets) or refused (an
// unprivileged user without them), and a refusal does not stop the process.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/integration/child_process.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

constexpr int kTimeoutMs = 10000;
constexpr int kSchedFifo = 1;  // SCHED_FIFO in <sched.h>

// Field 41 of /proc/PID/stat (proc(5)): the scheduling policy. Fields are counted after the
// command name, which is in parentheses and may hold spaces.
int scheduling_policy(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::istringstream rest(stat.substr(stat.rfind(')') + 2));
  std::string field;
  for (int i = 3; i <= 41 && rest >> field; ++i) {
  }
  return std::stoi(field);
}

// VmLck of /proc/PID/status, kB.
long locked_kb(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("VmLck:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

// AddressSanitizer intercepts mlockall and ignores it (it cannot lock its shadow memory): the call
// succeeds and the kernel shows nothing locked. Only an uninstrumented build can be checked.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kMlockHonoured = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kMlockHonoured = false;
#else
constexpr bool kMlockHonoured = true;
#endif
#else
constexpr bool kMlockHonoured = true;
#endif

class RunPriorityTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir();
    std::filesystem::permissions(dir_, std::filesystem::perms::all);  // readable by the unprivileged run
    config_ = write_file(dir_ / "vn300.yaml", "device: vn300\n");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Starts `prefix` + navfuse run with both requests on an idle TCP input, checks that each
  // report matches the kernel's view, and returns the output.
  std::string run_and_check(const std::vector<std::string>& prefix) {
    std::vector<std::string> argv = prefix;
    argv.insert(argv.end(), {navfuse_binary(), "run", "--config", config_, "--in",
                             "vn:tcp-listen://127.0.0.1:" + std::to_string(free_port(SOCK_STREAM)), "--rt-priority",
                             "1", "--lock-memory", "--quiet"});
    ChildProcess nav(argv, (dir_ / "nav.log").string());
    EXPECT_TRUE(nav.wait_for_output("running", kTimeoutMs)) << nav.output();
    const std::string out = nav.output();
    const bool fifo = out.find("SCHED_FIFO priority 1 in effect") != std::string::npos;
    EXPECT_TRUE(fifo || out.find("SCHED_FIFO priority 1 not permitted") != std::string::npos) << out;
    EXPECT_EQ(scheduling_policy(nav.pid()) == kSchedFifo, fifo) << out;
    const bool locked = out.find("memory: locked in RAM") != std::string::npos;
    EXPECT_TRUE(locked || out.find("mlockall not permitted") != std::string::npos) << out;
    if (kMlockHonoured) {
      EXPECT_EQ(locked_kb(nav.pid()) > 0, locked) << out;
    }
    nav.send(SIGTERM);
    const auto code = nav.wait_exit(kTimeoutMs);
    EXPECT_TRUE(code.has_value());
    EXPECT_EQ(code.value_or(-1), 0) << nav.output();
    return out;
  }

  std::filesystem::path dir_;
  std::string config_;
};

TEST_F(RunPriorityTest, ReportsWhatTheKernelGranted) { run_and_check({}); }

TEST_F(RunPriorityTest, RefusedRequestsAreReportedAndTheProcessRunsOn) {
  if (::geteuid() != 0 || !std::filesystem::exists("/usr/bin/setpriv")) {
    GTEST_SKIP() << "needs root and setpriv to run navfuse as an unprivileged user";
  }
  // nobody: no capabilities, RLIMIT_RTPRIO 0 (the default), so SCHED_FIFO must be refused.
  const std::vector<std::string> nobody = {"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"};
  std::vector<std::string> help = nobody;
  help.insert(help.end(), {navfuse_binary(), "--help"});
  if (run_to_exit(help, (dir_ / "help.log").string()).exit_code != 0) {
    GTEST_SKIP() << "the navfuse binary is not runnable by an unprivileged user here";
  }
  const std::string out = run_and_check(nobody);
  EXPECT_NE(out.find("SCHED_FIFO priority 1 not permitted"), std::string::npos) << out;
}

}  // namespace
}  // namespace navfuse::test

// Exit codes and Ctrl-C / SIGTERM of the batch commands (replay, bench, decode, sim) and write
// errors of `run`, through the real binary (issue 15, "exit codes" and "interruptions"):
//  - 2 when the command ran but produced nothing useful (no frame decoded, no pose in navigation
//    although poses were asked for, nothing to compare); --allow-empty keeps 0;
//  - 1 on a write error (/dev/full: written in place, never replaced; a FIFO whose reader left);
//  - 130 / 143 after SIGINT / SIGTERM, with complete frames in the outputs and the summary
//    saying so, also when the output's reader has stalled.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <mutex>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "test_paths.hpp"

namespace navfuse::test {
namespace {

const std::string kDemo = std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/";

bool contains(const std::string& text, const std::string& needle) { return text.find(needle) != std::string::npos; }

std::vector<std::uint8_t> read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

nlohmann::json read_json(const std::filesystem::path& path) { return nlohmann::json::parse(read_text_file(path.string())); }

// A FIFO reader on its own thread: opens `path`, reads `before_signal` bytes, then waits for
// `go_on` and reads to the end (or never reads again when `stall`).
class FifoReader {
 public:
  FifoReader(std::filesystem::path path, std::size_t before_signal, bool stall)
      : thread_([this, path = std::move(path), before_signal, stall] {
          const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
          if (fd < 0) return;
          std::vector<std::uint8_t> buf(4096);
          for (;;) {
            const bool waiting = bytes_.size() >= before_signal && !go_on_.load();
            if (waiting) {
              if (stall && stop_.load()) break;
              std::this_thread::sleep_for(std::chrono::milliseconds(5));
              continue;
            }
            const ssize_t n = ::read(fd, buf.data(), buf.size());
            if (n <= 0) break;
            std::lock_guard lock(mutex_);
            bytes_.insert(bytes_.end(), buf.begin(), buf.begin() + n);
            read_.store(bytes_.size());
          }
          ::close(fd);
        }) {}
  ~FifoReader() {
    go_on_.store(true);
    stop_.store(true);
    if (thread_.joinable()) thread_.join();
  }
  bool wait_for(std::size_t n, int timeout_ms) const {
    for (int i = 0; i < timeout_ms / 5; ++i) {
      if (read_.load() >= n) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }
  void go_on() { go_on_.store(true); }
  std::vector<std::uint8_t> finish() {
    go_on_.store(true);
    stop_.store(true);
    thread_.join();
    return bytes_;
  }

 private:
  std::vector<std::uint8_t> bytes_;
  std::mutex mutex_;
  std::atomic<std::size_t> read_{0};
  std::atomic<bool> go_on_{false}, stop_{false};
  std::thread thread_;
};

class BatchCommands : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir();
    // static_start: 60 s stationary; levels (vertical gyro) but never has a heading, so no pose
    // is ever in navigation.
    static_log_ = (dir_ / "static.vnb").string();
    ASSERT_EQ(run("sim", {"--scenario", "static_start", "--format", "vn", "--out", static_log_, "--quiet"}).exit_code, 0);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  RunResult run(const std::string& command, std::vector<std::string> args, int timeout_ms = 60000) {
    args.insert(args.begin(), {navfuse_binary(), command});
    return run_to_exit(args, (dir_ / ("log_" + std::to_string(runs_++))).string(), timeout_ms);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string make_fifo(const std::string& name) const {
    const std::string p = path(name);
    EXPECT_EQ(::mkfifo(p.c_str(), 0600), 0);
    return p;
  }
  // A child that must end within a few seconds of a signal: its exit code, or -1.
  static int exit_after(ChildProcess& child, int timeout_ms = 10000) {
    const auto code = child.wait_exit(timeout_ms);
    return code.value_or(-1);
  }

  std::filesystem::path dir_;
  std::string static_log_;
  int runs_ = 0;
};

TEST_F(BatchCommands, ReplayWithoutPoseInNavigationExits2UnlessAllowEmpty) {
  const auto refused = run("replay", {static_log_, "--csv", path("out.csv"), "--quiet"});
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_TRUE(contains(refused.output, "poses written is in navigation (modes reached: initializing, vertical_gyro)"))
      << refused.output;
  EXPECT_TRUE(std::filesystem::exists(path("out.csv")));  // the output is still written

  const auto allowed = run("replay", {static_log_, "--csv", path("out2.csv"), "--quiet", "--allow-empty"});
  EXPECT_EQ(allowed.exit_code, 0) << allowed.output;
  EXPECT_TRUE(contains(allowed.output, "warning: replay produced nothing useful")) << allowed.output;
  // No pose asked for: levelling is what the log offers, exit 0.
  EXPECT_EQ(run("replay", {static_log_, "--quiet"}).exit_code, 0);
  // The demo log navigates: exit 0 with every output.
  EXPECT_EQ(run("replay", {kDemo + "vn300.vnb", "--config", kDemo + "vn300.yaml", "--csv", path("demo.csv"), "--quiet"})
                .exit_code,
            0);
}

TEST_F(BatchCommands, NoFrameDecodedExits2InDecodeReplayAndBench) {
  for (const std::string command : {"decode", "replay", "bench"}) {
    std::vector<std::string> args{"mip:" + static_log_};
    if (command == "bench") args.insert(args.end(), {"--report", path("report_" + command), "--no-html"});
    if (command == "decode") args.insert(args.end(), {"-o", path("decoded.csv")});
    const auto r = run(command, args);
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, command + " produced nothing useful: no frame decoded from mip:" + static_log_))
        << r.output;
    args.push_back("--allow-empty");
    EXPECT_EQ(run(command, args).exit_code, 0) << command;
  }
}

TEST_F(BatchCommands, BenchWithoutNavigationExits2) {
  const auto r = run("bench", {static_log_, "--report", path("report"), "--no-html"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "navfuse reached no navigation solution")) << r.output;
}

TEST_F(BatchCommands, MostImuSamplesRejectedIsWarned) {
  // Three copies of one log: the second and third are dated before the end of the first, so
  // 2/3 of the IMU samples are rejected as time_backwards.
  auto bytes = read_all(static_log_);
  const auto once = bytes;
  for (int i = 0; i < 2; ++i) bytes.insert(bytes.end(), once.begin(), once.end());
  std::ofstream(path("thrice.vnb"), std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  const auto r = run("replay", {"vn:" + path("thrice.vnb"), "--summary-json", path("summary.json")});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // static_start: 60 s of 200 Hz IMU (apps/sim/scenarios.cpp).
  EXPECT_TRUE(contains(r.output, "warning: most imu samples were rejected: 24000 of 36000 (time_backwards: 24000)"))
      << r.output;
  const auto summary = read_json(path("summary.json"));
  ASSERT_TRUE(summary.contains("warnings"));
  // The GNSS fixes of the later copies went back in time too.
  EXPECT_EQ(summary["warnings"][0], "most imu samples were rejected: 24000 of 36000 (time_backwards: 24000)");
  EXPECT_TRUE(contains(summary["warnings"].dump(), "most gnss_position samples were rejected")) << summary["warnings"];
  // One copy: no warning.
  EXPECT_FALSE(contains(run("replay", {static_log_}).output, "warning"));
}

TEST_F(BatchCommands, WriteErrorsExit1AndDevFullStaysADevice) {
  const auto sim = run("sim", {"--scenario", "static_start", "--format", "vn", "--out", "/dev/full"});
  EXPECT_EQ(sim.exit_code, 1) << sim.output;
  EXPECT_TRUE(contains(sim.output, "cannot write '/dev/full'")) << sim.output;
  EXPECT_FALSE(contains(sim.output, "bytes;")) << "no report of bytes written: " << sim.output;

  const auto decode = run("decode", {static_log_, "-o", "/dev/full"});
  EXPECT_EQ(decode.exit_code, 1) << decode.output;
  EXPECT_TRUE(contains(decode.output, "No space left on device")) << decode.output;

  const auto replay = run("replay", {kDemo + "vn300.vnb", "--fe-out", "/dev/full", "--quiet"});
  EXPECT_EQ(replay.exit_code, 1) << replay.output;

  const auto live = run("run", {"--config", kDemo + "vn300.yaml", "--in", "vn:file:" + kDemo + "vn300.vnb", "--fe-out",
                                "file:/dev/full", "--quiet", "--summary-json", path("run.json")});
  EXPECT_EQ(live.exit_code, 1) << live.output;
  EXPECT_TRUE(contains(live.output, "--fe-out file:/dev/full: write: No space left on device")) << live.output;
  EXPECT_TRUE(contains(read_json(path("run.json"))["output_errors"][0].get<std::string>(), "bytes lost"));

  struct stat st {};
  ASSERT_EQ(::stat("/dev/full", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/full was replaced";
}

TEST_F(BatchCommands, RunReportsAFifoWhoseReaderLeft) {
  const std::string fifo = make_fifo("out.fifo");
  std::thread reader([&] {
    const int fd = ::open(fifo.c_str(), O_RDONLY | O_CLOEXEC);
    std::vector<std::uint8_t> buf(1000);
    [[maybe_unused]] const ssize_t n = ::read(fd, buf.data(), buf.size());
    ::close(fd);  // gone after the first kilobyte: the next writes fail with EPIPE
  });
  const auto live = run("run", {"--config", kDemo + "vn300.yaml", "--in", "vn:file:" + kDemo + "vn300.vnb", "--fe-out",
                                "file:" + fifo, "--quiet"});
  reader.join();
  EXPECT_EQ(live.exit_code, 1) << live.output;
  EXPECT_TRUE(contains(live.output, "Broken pipe")) << live.output;
}

TEST_F(BatchCommands, SimStopsOnSigintWithCompleteFramesInAFifo) {
  const std::string fifo = make_fifo("sim.fifo");
  FifoReader reader(fifo, 200'000, /*stall=*/false);
  // drive_outage: 20 minutes of driving, ~46 MB of VN-300 frames: far more than is read here.
  ChildProcess child({navfuse_binary(), "sim", "--scenario", "drive_outage", "--format", "vn", "--out", fifo},
                     path("sim.log"));
  ASSERT_TRUE(reader.wait_for(200'000, 20000));
  child.send(SIGINT);
  reader.go_on();
  EXPECT_EQ(exit_after(child), 130) << child.output();
  EXPECT_TRUE(contains(child.output(), "interrupted by signal 2")) << child.output();
  const auto bytes = reader.finish();
  EXPECT_LT(bytes.size(), 40'000'000u);
  std::ofstream(path("cut.vnb"), std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  const auto decoded = run("decode", {"vn:" + path("cut.vnb"), "-o", "/dev/null", "--summary-json", path("cut.json")});
  EXPECT_EQ(decoded.exit_code, 0) << decoded.output;
  const auto input = read_json(path("cut.json"))["inputs"][0];
  EXPECT_EQ(input["bad_frames"], 0);
  EXPECT_EQ(input["skipped_bytes"], 0) << "the last frame was cut";
}

TEST_F(BatchCommands, SigtermEndsACommandBlockedOnAStalledFifo) {
  for (const std::string command : {"sim", "decode"}) {
    SCOPED_TRACE(command);
    const std::string fifo = make_fifo(command + ".fifo");
    FifoReader reader(fifo, 100'000, /*stall=*/true);  // takes 100 kB, then never reads again
    std::vector<std::string> argv{navfuse_binary(), command};
    if (command == "sim") {
      argv.insert(argv.end(), {"--scenario", "drive_outage", "--format", "vn", "--out", fifo});
    } else {
      argv.insert(argv.end(), {kDemo + "vn300.vnb", "-o", fifo});
    }
    ChildProcess child(argv, path(command + ".log"));
    ASSERT_TRUE(reader.wait_for(100'000, 20000));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the writer fills the pipe and blocks
    child.send(SIGTERM);
    EXPECT_EQ(exit_after(child, 5000), 143) << child.output();
    EXPECT_TRUE(contains(child.output(), "its reader took no more data")) << child.output();
  }
}

TEST_F(BatchCommands, DecodeStopsOnSigintWithWholeRecordsAndSaysSo) {
  const std::string fifo = make_fifo("decode.fifo");
  FifoReader reader(fifo, 300'000, /*stall=*/false);
  ChildProcess child({navfuse_binary(), "decode", kDemo + "vn300.vnb", "-o", fifo, "--summary-json", path("d.json")},
                     path("decode.log"));
  ASSERT_TRUE(reader.wait_for(300'000, 20000));
  child.send(SIGINT);
  reader.go_on();
  EXPECT_EQ(exit_after(child), 130) << child.output();
  const auto bytes = reader.finish();
  ASSERT_FALSE(bytes.empty());
  EXPECT_EQ(bytes.back(), '\n') << "the last record was cut";
  EXPECT_TRUE(contains(child.output(), "interrupted by signal 2")) << child.output();
  EXPECT_EQ(read_json(path("d.json"))["interrupted_by_signal"], SIGINT);
}

TEST_F(BatchCommands, BenchStopsOnSigintAndReportsThePartRead) {
  // The log comes through a FIFO the test feeds: half of it, then the signal, then the rest.
  const std::string log = path("drive.vnb");
  ASSERT_EQ(run("sim", {"--scenario", "drive_outage", "--format", "vn", "--out", log, "--quiet"}).exit_code, 0);
  const auto bytes = read_all(log);
  const std::string fifo = make_fifo("bench.fifo");
  ChildProcess child({navfuse_binary(), "bench", "vn:" + fifo, "--report", path("report"), "--no-html", "--quiet"},
                     path("bench.log"));
  const int fd = ::open(fifo.c_str(), O_WRONLY | O_CLOEXEC);
  ASSERT_GE(fd, 0);
  const auto write_part = [&](std::size_t from, std::size_t to) {
    for (std::size_t at = from; at < to;) {
      const ssize_t n = ::write(fd, bytes.data() + at, std::min<std::size_t>(65536, to - at));
      if (n <= 0) return;
      at += static_cast<std::size_t>(n);
    }
  };
  write_part(0, bytes.size() / 2);
  child.send(SIGINT);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  signal(SIGPIPE, SIG_IGN);  // bench may stop reading before the rest is written
  write_part(bytes.size() / 2, bytes.size());
  ::close(fd);
  EXPECT_EQ(exit_after(child, 30000), 130) << child.output();
  EXPECT_TRUE(contains(child.output(), "interrupted by signal 2: the report covers the first")) << child.output();
  const auto metrics = read_json(path("report/metrics.json"));
  EXPECT_EQ(metrics["log"]["run"]["interrupted_by_signal"], SIGINT);
  EXPECT_GT(metrics["navfuse_vs_device"]["samples"].get<int>(), 0);
  EXPECT_LT(metrics["log"]["duration_s"].get<double>(), 0.9 * 1200.0);
}

}  // namespace
}  // namespace navfuse::test

// Live latency of `navfuse run` (a program, not a test: timing is measured, never asserted).
//
// A simulated VN-300 streams over a pseudo-terminal in real time, one write per measurement as a
// device would send it, with output.rate_hz 0 (a pose per IMU sample) and LCM publishing. Prints:
//  - end to end: from writing an IMU sample's bytes into the pty to receiving its pose on
//    NAVFUSE_POSE in this process (includes the pty and LCM delivery);
//  - in process: what the nav process itself reports on NAVFUSE_STATUS (IMU bytes read ->
//    pose published), p50/p99 per status interval.
// Usage: run_latency [seconds of data, default 20]
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>

#include <lcm/lcm-cpp.hpp>

#include "apps/lcm/lcm_channels.hpp"
#include "navfuse/pose_t.hpp"
#include "navfuse/status_t.hpp"
#include "tests/integration/child_process.hpp"
#include "tests/integration/pty_device.hpp"
#include "tests/integration/sim_log.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(std::min<double>(static_cast<double>(v.size()) - 1, p / 100.0 * static_cast<double>(v.size())));
  return v[i];
}

struct Collector {
  std::mutex mutex;
  std::map<std::int64_t, Clock::time_point> written;  // IMU time -> when its bytes were written
  std::vector<double> end_to_end_us;
  std::vector<double> status_p50_us, status_p99_us;

  void on_pose(const lcm::ReceiveBuffer*, const std::string&, const navfuse::pose_t* m) {
    const auto now = Clock::now();
    std::lock_guard lock(mutex);
    const auto it = written.find(m->time_gps_ns);
    if (it != written.end()) end_to_end_us.push_back(std::chrono::duration<double, std::micro>(now - it->second).count());
  }
  void on_status(const lcm::ReceiveBuffer*, const std::string&, const navfuse::status_t* m) {
    std::lock_guard lock(mutex);
    if (m->latency_p50_us > 0) {
      status_p50_us.push_back(m->latency_p50_us);
      status_p99_us.push_back(m->latency_p99_us);
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  using namespace navfuse;
  const double seconds = argc > 1 ? std::atof(argv[1]) : 20.0;
  const auto dir = std::filesystem::temp_directory_path() / ("navfuse_latency_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string config = (dir / "vn300.yaml").string();
  std::FILE* f = std::fopen(config.c_str(), "w");
  std::fputs("device: vn300\noutput:\n  rate_hz: 0\n", f);
  std::fclose(f);
  const std::string url = "udpm://239.255.76.67:" + std::to_string(20000 + ::getpid() % 40000) + "?ttl=0";

  const test::SimLog log = test::make_sim_log("drive_short", "vn", seconds + 1.0);
  test::PtyDevice device((dir / "ttyVN").string());
  Collector c;
  lcm::LCM lcm(url);
  lcm.subscribe(apps::kPoseChannel, &Collector::on_pose, &c);
  lcm.subscribe(apps::kStatusChannel, &Collector::on_status, &c);
  bool stop = false;
  std::thread lcm_thread([&] {
    while (!stop) lcm.handleTimeout(50);
  });

  test::ChildProcess nav({std::string(NAVFUSE_BINARY), "run", "--config", config, "--in",
                          "vn:serial:" + device.link() + "?baud=921600", "--lcm", url, "--quiet"},
                         (dir / "nav.log").string());
  if (!nav.wait_for_output("running", 10000)) {
    std::fprintf(stderr, "navfuse run did not start:\n%s\n", nav.output().c_str());
    return 1;
  }
  device.release_slave();

  // Real time: each measurement's bytes at its delivery time.
  const auto start = Clock::now();
  std::size_t begin = 0;
  for (const auto& piece : log.pieces) {
    const auto due = start + std::chrono::nanoseconds(piece.delivery_ns - log.start_ns);
    std::this_thread::sleep_until(due);
    {
      std::lock_guard lock(c.mutex);
      c.written[piece.delivery_ns] = Clock::now();  // IMU samples are delivered at their stamp
    }
    if (!device.write_all(log.bytes.data() + begin, piece.end - begin)) break;
    begin = piece.end;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // last poses and one more status
  nav.send(SIGTERM);
  const auto code = nav.wait_exit(5000);
  stop = true;
  lcm_thread.join();
  std::filesystem::remove_all(dir);

  std::lock_guard lock(c.mutex);
  std::printf("navfuse run latency, %.0f s of a 200 Hz VN-300 over a pty, pose per IMU sample, LCM udpm ttl=0\n",
              seconds);
  std::printf("  end to end (pty write -> NAVFUSE_POSE received): %zu poses, p50 %.0f us, p99 %.0f us, max %.0f us\n",
              c.end_to_end_us.size(), percentile(c.end_to_end_us, 50), percentile(c.end_to_end_us, 99),
              percentile(c.end_to_end_us, 100));
  std::printf("  in process (NAVFUSE_STATUS, bytes read -> published): %zu windows, median p50 %.0f us, "
              "median p99 %.0f us, worst p99 %.0f us\n",
              c.status_p99_us.size(), percentile(c.status_p50_us, 50), percentile(c.status_p99_us, 50),
              percentile(c.status_p99_us, 100));
  std::printf("  exit code after SIGTERM: %d\n", code.value_or(-1));
  return 0;
}

// The live nav process end to end, as on a companion computer: `navfuse run` reads a simulated
// VN-300 (simulator + VN encoder) over a pseudo-terminal serial port, takes aiding from
// `navfuse aid` over LCM, publishes poses on NAVFUSE_POSE, streams FusionEngine on a TCP listener
// whose SetMessageRate command changes the pose rate, survives the device being unplugged and
// plugged back in, and exits 0 on SIGTERM with its outputs complete.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <mutex>
#include <thread>

#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>

#include "apps/lcm/lcm_channels.hpp"
#include "frontends/mip/framer.hpp"
#include "navfuse/imu_t.hpp"
#include "navfuse/pose_t.hpp"
#include "navfuse/status_t.hpp"
#include "tests/integration/child_process.hpp"
#include "tests/integration/fe_client.hpp"
#include "tests/integration/pty_device.hpp"
#include "tests/integration/sim_log.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

constexpr int kTimeoutMs = 10000;
constexpr double kSpeedUp = 10.0;  // the log is played 10x faster than real time

// Services an LCM handle on its own thread, keeping what the test looks at.
class LcmListener {
 public:
  explicit LcmListener(const std::string& url) : lcm_(url) {
    lcm_.subscribe(apps::kPoseChannel, &LcmListener::on_pose, this);
    lcm_.subscribe(apps::kStatusChannel, &LcmListener::on_status, this);
    lcm_.subscribe(apps::kImuChannel, &LcmListener::on_imu, this);
    thread_ = std::thread([this] {
      while (!stop_) lcm_.handleTimeout(50);
    });
  }
  ~LcmListener() {
    stop_ = true;
    thread_.join();
  }
  bool good() { return lcm_.good(); }
  std::vector<std::int64_t> pose_times() {
    std::lock_guard lock(mutex_);
    return pose_times_;
  }
  std::vector<std::int64_t> imu_times() {
    std::lock_guard lock(mutex_);
    return imu_times_;
  }
  std::optional<navfuse::status_t> last_status() {
    std::lock_guard lock(mutex_);
    return status_;
  }
  // Waits up to timeout_ms for a pose stamped at or after `time_ns`.
  bool wait_pose_after(std::int64_t time_ns, int timeout_ms) {
    const io::Deadline deadline(timeout_ms);
    while (!deadline.expired()) {
      {
        std::lock_guard lock(mutex_);
        if (!pose_times_.empty() && pose_times_.back() >= time_ns) return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }

 private:
  void on_pose(const lcm::ReceiveBuffer*, const std::string&, const navfuse::pose_t* m) {
    std::lock_guard lock(mutex_);
    pose_times_.push_back(m->time_gps_ns);
  }
  void on_imu(const lcm::ReceiveBuffer*, const std::string&, const navfuse::imu_t* m) {
    std::lock_guard lock(mutex_);
    imu_times_.push_back(m->time_gps_ns);
  }
  void on_status(const lcm::ReceiveBuffer*, const std::string&, const navfuse::status_t* m) {
    std::lock_guard lock(mutex_);
    status_ = *m;
  }
  lcm::LCM lcm_;
  std::mutex mutex_;
  std::vector<std::int64_t> pose_times_;
  std::vector<std::int64_t> imu_times_;
  std::optional<navfuse::status_t> status_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

std::size_t piece_at(const SimLog& log, double seconds) {
  const std::int64_t t = log.start_ns + static_cast<std::int64_t>(seconds * 1e9);
  return static_cast<std::size_t>(std::lower_bound(log.pieces.begin(), log.pieces.end(), t,
                                                   [](const SimLog::Piece& p, std::int64_t v) { return p.delivery_ns < v; }) -
                                  log.pieces.begin());
}

// Median spacing of the pose times at or after `from_ns`, seconds.
double median_spacing_s(const std::vector<std::int64_t>& times, std::int64_t from_ns) {
  std::vector<double> d;
  for (std::size_t i = 1; i < times.size(); ++i) {
    if (times[i - 1] >= from_ns) d.push_back(static_cast<double>(times[i] - times[i - 1]) * 1e-9);
  }
  if (d.empty()) return 0.0;
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

using RunLiveTest = ScratchDirTest;

TEST_F(RunLiveTest, SerialDeviceLcmAidingFeCommandsReplugAndSigterm) {
  const SimLog log = make_sim_log("drive_short", "vn", 40.0);
  ASSERT_GT(log.pieces.size(), 1000u);
  const std::string config = write_file(dir_ / "vn300.yaml", "device: vn300\noutput:\n  rate_hz: 50\n");
  const std::string lcm_url = private_lcm_url(2);
  const std::uint16_t fe_port = free_port(SOCK_STREAM);
  const std::string mip_out = (dir_ / "out.mip").string();
  const std::string summary = (dir_ / "summary.json").string();

  PtyDevice device((dir_ / "ttyVN").string());
  LcmListener listener(lcm_url);
  ASSERT_TRUE(listener.good());
  ChildProcess nav({navfuse_binary(), "run", "--config", config, "--in",
                    "vn:serial:" + device.link() + "?baud=921600&reconnect_ms=20&max_reconnect_ms=100",
                    "--fe-out", "tcp-listen://127.0.0.1:" + std::to_string(fe_port), "--mip-out", "file:" + mip_out,
                    "--lcm", lcm_url, "--status-interval", "0.2", "--summary-json", summary},
                   (dir_ / "nav.log").string());
  ASSERT_TRUE(nav.wait_for_output("running", kTimeoutMs)) << nav.output();
  device.release_slave();  // the nav process holds the port now (and has made it raw)
  FeClient fe;
  ASSERT_TRUE(fe.connect(fe_port, kTimeoutMs));

  // 1. The first 15 s of the drive: poses on LCM and FusionEngine poses on TCP at 50 Hz.
  const std::size_t cut1 = piece_at(log, 15.0);
  ASSERT_TRUE(play(device, log, 0, cut1, kSpeedUp));
  const std::int64_t t1 = log.pieces[cut1 - 1].delivery_ns;
  ASSERT_TRUE(listener.wait_pose_after(t1 - 100'000'000, kTimeoutMs)) << nav.output();

  // 2. External position aiding from `navfuse aid` over LCM, stamped inside the data.
  const RunResult aid = run_to_exit({navfuse_binary(), "aid", "position", "45.0", "7.0", "300", "--std", "2",
                                     "--time-gps-s", std::to_string(static_cast<double>(t1) * 1e-9 - 0.5), "--lcm",
                                     lcm_url},
                                    (dir_ / "aid.log").string());
  ASSERT_EQ(aid.exit_code, 0) << aid.output;

  // 3. SetMessageRate: Pose every 100 ms instead of output.rate_hz; the device answers OK.
  frontends::fusionengine::SetMessageRateMessage rate;
  rate.protocol = static_cast<std::uint8_t>(frontends::fusionengine::ProtocolType::kFusionEngine);
  rate.message_id = frontends::fusionengine::to_u16(frontends::fusionengine::MessageType::kPose);
  rate.rate = static_cast<std::uint8_t>(frontends::fusionengine::MessageRate::k100Ms);
  const std::uint32_t sequence = fe.send(rate);
  const io::Deadline answered(kTimeoutMs);
  while (fe.snapshot().responses.empty() && !answered.expired()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const FeClient::Received before = fe.snapshot();
  ASSERT_EQ(before.responses.size(), 1u);
  EXPECT_EQ(before.responses[0].source_sequence, sequence);
  EXPECT_EQ(before.responses[0].response, static_cast<std::uint8_t>(frontends::fusionengine::Response::kOk));
  EXPECT_NEAR(median_spacing_s(before.pose_times_ns, log.start_ns), 0.02, 1e-3);

  // 4. Unplug the device and plug it back in: the process keeps running and reopens it.
  device.unplug();
  ASSERT_TRUE(nav.wait_for_output("lost", kTimeoutMs)) << nav.output();
  ASSERT_TRUE(device.plug());
  ASSERT_TRUE(nav.wait_for_output("re-opened", kTimeoutMs)) << nav.output();
  device.release_slave();
  EXPECT_FALSE(nav.wait_exit(0).has_value());

  // 5. The next 15 s: fusion resumes (new poses on LCM), FusionEngine poses now at 10 Hz.
  const std::size_t cut2 = piece_at(log, 30.0);
  ASSERT_TRUE(play(device, log, cut1, cut2, kSpeedUp));
  const std::int64_t t2 = log.pieces[cut2 - 1].delivery_ns;
  ASSERT_TRUE(listener.wait_pose_after(t2 - 100'000'000, kTimeoutMs)) << nav.output();
  const io::Deadline streamed(kTimeoutMs);
  while (!streamed.expired() && (fe.snapshot().pose_times_ns.empty() || fe.snapshot().pose_times_ns.back() < t2 - 200'000'000)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const FeClient::Received after = fe.snapshot();
  EXPECT_NEAR(median_spacing_s(after.pose_times_ns, t1 + 1'000'000'000), 0.1, 1e-3);
  const auto status = listener.last_status();
  ASSERT_TRUE(status.has_value());
  ASSERT_EQ(status->num_inputs, 1);
  EXPECT_GE(status->inputs[0].reconnects, 1);
  EXPECT_GT(status->latency_p99_us, 0.0f);
  // NAVFUSE_IMU goes out with each NAVFUSE_POSE (output.rate_hz: 50 Hz), not at the 200 Hz IMU rate.
  const auto poses = listener.pose_times();
  const auto imus = listener.imu_times();
  EXPECT_GT(imus.size(), poses.size() / 2);
  EXPECT_LE(imus.size(), poses.size());
  // Each at the time of a pose (UDP may lose the odd pose on the way: allow 1 %).
  const auto unmatched = std::count_if(imus.begin(), imus.end(), [&](std::int64_t t) {
    return !std::binary_search(poses.begin(), poses.end(), t);
  });
  EXPECT_LE(unmatched * 100, static_cast<std::ptrdiff_t>(imus.size())) << unmatched << " of " << imus.size();

  // 6. SIGTERM: exit 0 promptly, outputs complete.
  nav.send(SIGTERM);
  const auto code = nav.wait_exit(5000);
  ASSERT_TRUE(code.has_value()) << "still running after SIGTERM";
  EXPECT_EQ(*code, 0) << nav.output();
  const auto j = nlohmann::json::parse(read_text_file(summary));
  EXPECT_GE(j["measurements"]["external_position"]["decoded"].get<int>(), 1) << j.dump();
  EXPECT_GT(j["measurements"]["imu"]["used"].get<int>(), 4000) << j.dump();
  const std::string mip = read_text_file(mip_out);
  frontends::mip::Framer framer;
  std::size_t packets = 0;
  framer.feed(std::span(reinterpret_cast<const std::uint8_t*>(mip.data()), mip.size()),
              [&](const frontends::mip::PacketView&) { ++packets; });
  EXPECT_GT(packets, 100u);
  EXPECT_EQ(framer.counters().skipped_bytes, 0u);
  EXPECT_EQ(framer.buffered(), 0u);  // no half-written packet at the end
  const io::Deadline hung_up(kTimeoutMs);
  while (!fe.closed() && !hung_up.expired()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_TRUE(fe.closed());
}

}  // namespace
}  // namespace navfuse::test

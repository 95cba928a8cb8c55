// `navfuse replay --lcm URL`: the replayed poses arrive on NAVFUSE_POSE as real LCM traffic
// (loopback multicast), one per pose the replay reports, carrying the same solution as the CSV
// written by the same run (an independent encoder); NAVFUSE_IMU comes with each pose.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "apps/common/command_error.hpp"
#include "apps/replay/replay.hpp"
#include "navfuse/imu_t.hpp"
#include "navfuse/pose_t.hpp"
#include "tests/integration/lcm_receiver.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

// The first `bytes` of the bundled VN-300 demo log (about 20 s). The replay publishes it in a
// few milliseconds; the burst must stay well under the ~100 datagrams a loopback multicast
// socket queues with Linux's default receive buffer (each small datagram is charged ~2 KB).
std::string demo_head(const std::filesystem::path& dir, std::size_t bytes) {
  std::ifstream in(std::filesystem::path(NAVFUSE_SOURCE_DIR) / "data/demo/vn300.vnb", std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(bytes));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return write_file(dir / "head.vnb", head);
}

TEST(ReplayLcm, PosesArriveOnNavfusePoseWithTheCsvValues) {
  const auto dir = scratch_dir();
  const std::string url = private_lcm_url(7);
  lcm::LCM rx(url);
  ASSERT_TRUE(rx.good()) << url;
  LcmReceiver<navfuse::pose_t> poses(rx, "NAVFUSE_POSE");
  LcmReceiver<navfuse::imu_t> imus(rx, "NAVFUSE_IMU");
  std::atomic<bool> stop{false};
  std::thread pump([&] {
    while (!stop.load()) rx.handleTimeout(20);
  });

  apps::ReplayOptions o;
  o.inputs = {"vn:" + demo_head(dir, 400 * 1024)};
  o.allow_truncated = true;
  o.output_rate_hz = 1.0;
  o.csv_out = (dir / "poses.csv").string();
  o.lcm_url = url;
  const apps::ReplayResult r = apps::run_replay(o);
  ASSERT_GT(r.poses, 10u);

  // Everything published has been sent; give the pump a bounded time to take it in.
  for (int i = 0; i < 100 && poses.messages.size() < r.poses; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  stop = true;
  pump.join();

  EXPECT_EQ(poses.messages.size(), r.poses);
  EXPECT_GT(imus.messages.size(), 0u);  // one per pose once the attitude is known (1 Hz vs 200 Hz IMU)
  EXPECT_LE(imus.messages.size(), r.poses);
  const auto& lcm_stats = r.summary.extra.at("lcm");
  EXPECT_EQ(lcm_stats.at("failures").get<std::uint64_t>(), 0u);
  EXPECT_EQ(lcm_stats.at("published").get<std::uint64_t>(), poses.messages.size() + imus.messages.size());

  ASSERT_FALSE(poses.messages.empty());
  const navfuse::pose_t& last = poses.messages.back();
  const auto row = last_csv_row(o.csv_out);
  ASSERT_GE(row.size(), 6u);
  EXPECT_NEAR(last.time_gps_ns * 1e-9, std::stod(row[0]), 1e-6);
  EXPECT_NEAR(last.lat_deg, std::stod(row[3]), 1e-7);
  EXPECT_NEAR(last.lon_deg, std::stod(row[4]), 1e-7);
  EXPECT_NEAR(last.height_m, std::stod(row[5]), 1e-3);
  std::filesystem::remove_all(dir);
}

TEST(ReplayLcm, UnopenableUrlIsAOneLineError) {
  apps::ReplayOptions o;
  o.inputs = {(std::filesystem::path(NAVFUSE_SOURCE_DIR) / "data/demo/vn300.vnb").string()};
  o.lcm_url = "nosuchprovider://x";
  try {
    apps::run_replay(o);
    FAIL() << "expected a CommandError";
  } catch (const apps::CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("--lcm"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace navfuse::test

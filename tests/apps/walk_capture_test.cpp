// The real handheld walk in ../shared/captures/real/walk_0827 (README there) through the whole
// replay path with the capture's own config (data-sheet noise, unchanged) plus
// `platform: pedestrian`: the walker never reaches the land default's 2 m/s, so only the
// pedestrian profile (no NHC, alignment from a walking-speed course) gets past vertical_gyro.
// Skips when the shared captures are absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "apps/replay/replay.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

const std::filesystem::path kWalk = std::filesystem::path(NAVFUSE_SHARED_DIR) / "captures/real/walk_0827";

ReplayResult replay_walk(const std::string& platform_line) {
  const auto dir = testing::scratch_dir();
  testing::write_text(dir / "config.yaml", testing::read_text(kWalk / "config.yaml") + platform_line);
  ReplayOptions o;
  o.config_path = (dir / "config.yaml").string();
  o.inputs = {"imutxt:" + (kWalk / "imu.txt").string(), "rtklib:" + (kWalk / "gnss.pos").string()};
  return run_replay(o);
}

bool reached(const ReplayResult& r, const std::string& mode) {
  const auto& modes = r.summary.run->modes_reached;
  return std::find(modes.begin(), modes.end(), mode) != modes.end();
}

TEST(WalkCapture, PedestrianPlatformReachesNavigation) {
  if (!std::filesystem::exists(kWalk / "imu.txt")) GTEST_SKIP() << "capture not present";
  const ReplayResult walk = replay_walk("platform: pedestrian\n");
  ASSERT_TRUE(walk.summary.run);
  EXPECT_TRUE(reached(walk, "navigation"));
  EXPECT_EQ(walk.imu_samples, 20454u);  // every line of imu.txt (README)
  const auto& pos = walk.summary.kinds[static_cast<std::size_t>(MeasurementKind::kGnssPosition)];
  EXPECT_EQ(pos.decoded, 536u);
  EXPECT_GT(pos.used, 0u);
}

TEST(WalkCapture, LandDefaultStaysInVerticalGyro) {
  // The behaviour issue 14 reports, kept as the contrast that makes the test above meaningful.
  if (!std::filesystem::exists(kWalk / "imu.txt")) GTEST_SKIP() << "capture not present";
  const ReplayResult drive = replay_walk("");
  ASSERT_TRUE(drive.summary.run);
  EXPECT_TRUE(reached(drive, "vertical_gyro"));
  EXPECT_FALSE(reached(drive, "navigation"));
}

}  // namespace
}  // namespace navfuse::apps

// The real handheld walk in ../shared/captures/real/walk_0827 (README there) through the whole
// replay path with the capture's own config, unchanged (data-sheet noise, no platform, no
// heading): issue 14's check. The filter must align by itself at walking speed, use the RTK
// fixes instead of gating them out, stay within centimetres of them, and dead-reckon 10 s
// outages better than the published filters (walk README: KF-GINS 4.27 m, the upstream Python
// filter 3.99 m mean error at the end of the outages). Skips when the shared captures are absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "apps/replay/replay.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

const std::filesystem::path kWalk = std::filesystem::path(NAVFUSE_SHARED_DIR) / "captures/real/walk_0827";

ReplayOptions walk_options() {
  ReplayOptions o;
  o.config_path = (kWalk / "config.yaml").string();
  o.inputs = {"imutxt:" + (kWalk / "imu.txt").string(), "rtklib:" + (kWalk / "gnss.pos").string()};
  o.truth_path = "rtklib:" + (kWalk / "gnss.pos").string();
  return o;
}

bool reached(const ReplayResult& r, const std::string& mode) {
  const auto& modes = r.summary.run->modes_reached;
  return std::find(modes.begin(), modes.end(), mode) != modes.end();
}

struct FixedUse {
  int fixed = 0, used = 0;
};

// RTK-fixed epochs and how many were used, from 20 s after the first fix (the window the README
// scores), read from the innovations CSV of a replay.
FixedUse fixed_epochs_used(const std::string& innovations_csv) {
  std::ifstream in(innovations_csv);
  std::string line;
  std::getline(in, line);  // header
  double first_s = -1.0;
  FixedUse u;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string time, kind, fix, result;
    std::getline(row, time, ',');
    std::getline(row, kind, ',');
    std::getline(row, fix, ',');
    std::getline(row, result, ',');
    if (kind != "gnss_position") continue;
    const double t = std::stod(time);
    if (first_s < 0.0) first_s = t;
    if (fix != "rtk_fixed" || t - first_s < 20.0) continue;
    ++u.fixed;
    u.used += result == "used";
  }
  return u;
}

TEST(WalkCapture, UnchangedConfigFollowsTheWalk) {
  if (!std::filesystem::exists(kWalk / "imu.txt")) GTEST_SKIP() << "capture not present";
  const auto dir = testing::scratch_dir();
  ReplayOptions o = walk_options();
  o.innovations_csv = (dir / "innovations.csv").string();
  const ReplayResult walk = run_replay(o);
  ASSERT_TRUE(walk.summary.run);
  EXPECT_TRUE(reached(walk, "navigation"));
  EXPECT_EQ(walk.imu_samples, 20454u);  // every line of imu.txt (README)

  const FixedUse u = fixed_epochs_used(o.innovations_csv);
  EXPECT_EQ(u.fixed, 273);  // README: 273 fixed epochs from 20 s on
  EXPECT_GE(u.used, 0.98 * u.fixed) << u.used << " of " << u.fixed;

  const auto& h = walk.summary.extra["accuracy"]["horizontal_m"];
  EXPECT_LE(h["rms"].get<double>(), 0.03);
}

// The same walk with the solution's velocity columns removed, as RTKLIB writes a .pos without
// velocity output and as public GNSS text carries only positions: the heading must come from the
// fixes themselves (control/gnss_heading_alignment.hpp). Before, such a log never left
// vertical-gyro mode.
TEST(WalkCapture, PositionOnlyFixesAlignByThemselves) {
  if (!std::filesystem::exists(kWalk / "imu.txt")) GTEST_SKIP() << "capture not present";
  const auto dir = testing::scratch_dir();
  const std::filesystem::path positions = dir / "positions_only.pos";
  {
    std::ifstream in(kWalk / "gnss.pos");
    std::ofstream out(positions);
    std::string line;
    int rows = 0;
    while (std::getline(in, line)) {
      if (line.rfind("%  GPST", 0) == 0) line = line.substr(0, line.find("  vn(m/s)"));
      if (!line.empty() && line[0] != '%') {
        // date, time, lat, lon, height, Q, ns, sdn, sde, sdu, sdne, sdeu, sdun, age, ratio
        std::stringstream fields(line);
        std::string field, kept;
        for (int i = 0; i < 15 && fields >> field; ++i) kept += (i ? " " : "") + field;
        line = kept;
        ++rows;
      }
      out << line << '\n';
    }
    ASSERT_GT(rows, 500);
  }
  ReplayOptions o = walk_options();
  o.inputs[1] = "rtklib:" + positions.string();
  o.innovations_csv = (dir / "innovations.csv").string();
  const ReplayResult walk = run_replay(o);
  ASSERT_TRUE(walk.summary.run);
  EXPECT_TRUE(reached(walk, "navigation"));
  const nlohmann::ordered_json j = walk.summary.to_json(/*decode_only=*/false);
  EXPECT_EQ(j["measurements"]["gnss_velocity"]["decoded"].get<int>(), 0);
  EXPECT_GT(j["measurements"]["gnss_position"]["decoded"].get<int>(), 500);
  // Without the receiver's velocities the filter is held by positions alone and gates more of
  // them in the walker's sharp turns (265 of 273 on 2026-11-24; 270 with the velocities): 95 %
  // here, the 98 % of issue 14 holds for the walk as published (above).
  const FixedUse u = fixed_epochs_used(o.innovations_csv);
  EXPECT_EQ(u.fixed, 273);
  EXPECT_GE(u.used, 0.95 * u.fixed) << u.used << " of " << u.fixed;
  EXPECT_LE(walk.summary.extra["accuracy"]["horizontal_m"]["rms"].get<double>(), 0.03);
}

TEST(WalkCapture, OutagesEndBelowThePublishedFilters) {
  if (!std::filesystem::exists(kWalk / "imu.txt")) GTEST_SKIP() << "capture not present";
  ReplayOptions o = walk_options();
  // 10 s off every 30 s from 20 s after the first fix (the IMU starts 1.22 s after it).
  o.gnss_outage = "30:10:18.78";
  const ReplayResult walk = run_replay(o);
  const auto& end = walk.summary.extra["accuracy"]["gnss_outage"]["end_of_outage_horizontal_m"];
  ASSERT_GE(end["outages"].get<int>(), 2);
  EXPECT_LT(end["mean"].get<double>(), 3.99);  // the better of the two published means
}

}  // namespace
}  // namespace navfuse::apps

// References of other formats for `--truth`: an RTKLIB .pos compared at the antenna at its own
// epochs (the solution interpolated and moved by the lever arm), a KF-GINS .nav at the IMU, and
// the format detected from the bytes or given as a prefix. Expected values by hand: WGS-84 radii
// of curvature at 45 deg in closed form, the lever arm rotated by a yaw of 0.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "apps/common/command_error.hpp"
#include "apps/replay/truth_accuracy.hpp"
#include "apps/replay/truth_rows.hpp"
#include "core/rotation/rotation.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

using testing::scratch_dir;
using testing::write_text;

// Metres north / east per radian of latitude / longitude at 45 deg, height 10 m.
struct Radii45 {
  double north, east;
};
Radii45 radii45() {
  const double lat = 45.0 * rot::kDegToRad;
  const double a = 6378137.0, e2 = 6.69437999014e-3;
  const double w = std::sqrt(1.0 - e2 * std::sin(lat) * std::sin(lat));
  return {a * (1.0 - e2) / (w * w * w) + 10.0, (a / w + 10.0) * std::cos(lat)};
}

NavSolution pose(std::int64_t t_ns, double north_m) {
  NavSolution s;
  s.mode = NavMode::kNavigation;
  s.header.time_ns = t_ns;
  s.lat_rad = 45.0 * rot::kDegToRad + north_m / radii45().north;
  s.lon_rad = 7.0 * rot::kDegToRad;
  s.height_m = 10.0;
  s.vel_ned_mps = {200.0, 0.0, 0.0};  // 2 m in 10 ms
  return s;
}

TEST(TruthReference, RtklibIsComparedAtTheAntennaAtItsOwnEpochs) {
  const auto dir = scratch_dir();
  // Poses at 100.000 s (0 m north) and 100.010 s (2 m north), heading north; antenna 1 m to the
  // right (east). At the fixed epoch 100.005 s the antenna is 1 m north and 1 m east of the start.
  const Radii45 r = radii45();
  char line[256];
  std::snprintf(line, sizeof line, "0 100.005 %.11f %.11f 10.0 1 20 0.01 0.01 0.02 0 0 0 0 0 200 0 0 0 0 0 0 0 0\n",
                45.0 + (1.0 / r.north) * rot::kRadToDeg, 7.0 + (1.0 / r.east) * rot::kRadToDeg);
  write_text(dir / "ref.pos",
             "%  GPST latitude(deg) longitude(deg) height(m) Q ns sdn(m) sde(m) sdu(m) sdne(m) sdeu(m) sdun(m) age(s) "
             "ratio vn(m/s) ve(m/s) vu(m/s) sdvn sdve sdvu sdvne sdveu sdvun\n" +
                 std::string(line) +
                 "0 100.007 45.0 7.0 10.0 2 20 0.1 0.1 0.2 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n");  // float: not a reference
  TruthAccuracy acc((dir / "ref.pos").string(), Eigen::Vector3d(0.0, 1.0, 0.0));
  acc.add(pose(100'000'000'000LL, 0.0));
  acc.add(pose(100'010'000'000LL, 2.0));
  ASSERT_EQ(acc.samples(), 1u);
  EXPECT_LT(acc.summary(TruthAccuracy::kHorizontal).max, 1e-3);
  EXPECT_LT(acc.summary(TruthAccuracy::kVertical).max, 1e-3);
  EXPECT_LT(acc.summary(TruthAccuracy::kVelocity).max, 1e-9);
  EXPECT_EQ(acc.summary(TruthAccuracy::kHeading).samples, 0u);  // RTKLIB has no attitude
  const auto j = acc.to_json();
  EXPECT_EQ(j["reference"]["format"], "rtklib");
  EXPECT_EQ(j["reference"]["point"], "antenna");
  EXPECT_EQ(j["reference"]["rows_not_fixed_skipped"], 1);
  EXPECT_FALSE(j.contains("heading_deg"));

  // Without the lever arm the same solution is 1 m west of the antenna.
  TruthAccuracy at_imu((dir / "ref.pos").string());
  at_imu.add(pose(100'000'000'000LL, 0.0));
  at_imu.add(pose(100'010'000'000LL, 2.0));
  EXPECT_NEAR(at_imu.summary(TruthAccuracy::kHorizontal).max, 1.0, 1e-3);
}

TEST(TruthReference, KfGinsNavIsAtTheImuWithAttitude) {
  const auto dir = scratch_dir();
  // week 0, 100 s; 3 m north of the pose, velocity and attitude as written.
  char line[256];
  std::snprintf(line, sizeof line, "0 100.0 %.11f 7.0 12.0 1.0 2.0 0.3 1.0 2.0 31.0\n0 100.1 %.11f 7.0 12.0 1.0 2.0 0.3 1.0 2.0 31.0\n",
                45.0 + (3.0 / radii45().north) * rot::kRadToDeg, 45.0 + (3.0 / radii45().north) * rot::kRadToDeg);
  write_text(dir / "ref.nav", line);
  TruthAccuracy acc((dir / "ref.nav").string(), Eigen::Vector3d(5.0, 5.0, 5.0));  // ignored: IMU reference
  NavSolution s = pose(100'050'000'000LL, 0.0);
  s.vel_ned_mps = {1.0, 2.0, 0.0};
  s.rpy_rad = Eigen::Vector3d(1.0, 2.0, 30.0) * rot::kDegToRad;
  acc.add(s);
  ASSERT_EQ(acc.samples(), 1u);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kHorizontal).max, 3.0, 1e-3);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kVertical).max, 2.0, 1e-9);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kVelocity).max, 0.3, 1e-9);
  EXPECT_NEAR(acc.summary(TruthAccuracy::kHeading).max, 1.0, 1e-9);
  EXPECT_EQ(acc.to_json()["reference"]["point"], "imu");
}

TEST(TruthReference, FormatIsDetectedOrGivenAsAPrefix) {
  const auto dir = scratch_dir();
  write_text(dir / "a.txt", "2381 408639.749 40.0 -105.0 1600.0 1 25 0.01 0.01 0.01 0 0 0 0 0\n");
  write_text(dir / "b.txt", "2381 408639.749 40.0 -105.0 1600.0 0.1 0.2 0.3 1 2 3\n");
  write_text(dir / "c.txt", "time_gps_s,lat_deg,lon_deg,height_m,vn,ve,vd,roll_deg,pitch_deg,yaw_deg\n1,2,3,4,5,6,7,8,9,10\n");
  EXPECT_EQ(open_truth_rows((dir / "a.txt").string())->format(), "rtklib");
  EXPECT_EQ(open_truth_rows((dir / "b.txt").string())->format(), "nav");
  EXPECT_EQ(open_truth_rows((dir / "c.txt").string())->format(), "csv");
  EXPECT_EQ(open_truth_rows("nav:" + (dir / "b.txt").string())->format(), "nav");
  // Given as RTKLIB, a .nav line does not read: an error naming the file and line.
  auto rows = open_truth_rows("rtklib:" + (dir / "b.txt").string());
  TruthPoint p;
  try {
    rows->next(p);
    FAIL();
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("line 1"), std::string::npos);
  }
}

}  // namespace
}  // namespace navfuse::apps

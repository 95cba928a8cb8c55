// End-to-end: a simulated VN-300 drive with a GNSS outage plus a FusionEngine wheel-speed log
// (navfuse sim), replayed through the filter (navfuse replay). Checks against the simulator's
// truth, byte-identical repeat runs, and that the FusionEngine / MIP outputs decode with the
// front-ends. Label "scenario": ~40 k IMU samples per replay.
#include <filesystem>

#include <gtest/gtest.h>

#include "apps/common/frontend_registry.hpp"
#include "apps/replay/replay.hpp"
#include "apps/simcmd/sim_command.hpp"
#include "decode_counts.hpp"
#include "simulated_drive.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

using testing::decode_file;
using testing::read_bytes;

class ReplayScenario : public ::testing::Test {
 protected:
  // Each test simulates its own logs in its own directory: ctest runs the tests of this file as
  // separate processes in parallel, so nothing may be shared between them.
  void SetUp() override {
    dir_ = testing::scratch_dir();
    SimOptions o = testing::short_drive_sim(dir_, "wheel.p1log");
    o.device_rate_hz = 50.0;
    run_sim(o);
  }
  ReplayOptions options(const std::string& tag) {
    ReplayOptions r;
    r.config_path = std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/vn300.yaml";  // the simulated vehicle
    r.inputs = {(dir_ / "vn.bin").string(), (dir_ / "wheel.p1log").string()};
    r.truth_path = (dir_ / "truth.csv").string();
    r.fe_out = (dir_ / (tag + ".p1log")).string();
    r.mip_out = (dir_ / (tag + ".mip")).string();
    r.csv_out = (dir_ / (tag + ".csv")).string();
    return r;
  }
  std::filesystem::path dir_;
};

TEST_F(ReplayScenario, NavigatesWithinTheFilterGoalsAgainstTruth) {
  const ReplayResult r = run_replay(options("a"));
  const auto& modes = r.summary.run->modes_reached;
  EXPECT_NE(std::find(modes.begin(), modes.end(), "navigation"), modes.end());
  EXPECT_NE(std::find(modes.begin(), modes.end(), "dead_reckoning"), modes.end());
  EXPECT_EQ(r.imu_samples, 190u * 200u);
  // Both inputs merged: every wheel sample reached the filter on the IMU's time base.
  const auto& speed = r.summary.kinds[static_cast<std::size_t>(MeasurementKind::kVehicleSpeed)];
  EXPECT_EQ(speed.rejected.count("time_base"), 0u);
  EXPECT_GT(speed.used, 5000u);
  const auto& acc = r.summary.extra.at("accuracy");
  std::printf("horizontal RMS %.3f m, outage max %.3f m, heading RMS %.3f deg over %d poses\n",
              acc["horizontal_m"]["rms"].get<double>(), acc["gnss_outage"]["horizontal_m"]["max"].get<double>(),
              acc["heading_deg"]["rms"].get<double>(), acc["samples"].get<int>());
  EXPECT_GT(acc["samples"].get<int>(), 15000);
  // Filter goals (tests/filter/scenario_test.cpp): standalone GNSS 0.6 m horizontal RMS; with
  // wheel speed, at most 0.2 % of the distance after an outage (30 s at 20 m/s = 600 m: 1.2 m).
  EXPECT_LE(acc["horizontal_m"]["rms"].get<double>(), 0.6);
  EXPECT_LE(acc["gnss_outage"]["horizontal_m"]["max"].get<double>(), 0.002 * 600.0);
  EXPECT_LE(acc["heading_deg"]["rms"].get<double>(), 0.5);
}

TEST_F(ReplayScenario, RepeatRunsWriteIdenticalBytes) {
  run_replay(options("x"));
  run_replay(options("y"));
  for (const char* ext : {".p1log", ".mip", ".csv"}) {
    const auto x = read_bytes(dir_ / (std::string("x") + ext));
    const auto y = read_bytes(dir_ / (std::string("y") + ext));
    EXPECT_GT(x.size(), 100000u) << ext;
    EXPECT_TRUE(x == y) << ext << " differs between runs";
  }
}

TEST_F(ReplayScenario, OutputsDecodeWithTheFrontEnds) {
  const ReplayResult r = run_replay(options("d"));
  auto fe = decode_file(*find_frontend("fe"), dir_ / "d.p1log");
  EXPECT_EQ(fe.counters.bad_frames, 0u);
  // Pose + PoseAux (+ GNSSInfo) of one epoch decode as one device solution.
  EXPECT_EQ(fe.kinds["device_solution"], r.poses);
  // IMUOutput after every IMU sample once the attitude is known (after levelling).
  EXPECT_GT(fe.kinds["imu"], r.imu_samples * 9 / 10);
  EXPECT_LE(fe.kinds["imu"], r.imu_samples);
  auto mip = decode_file(*find_frontend("mip"), dir_ / "d.mip");
  EXPECT_EQ(mip.counters.bad_frames, 0u);
  EXPECT_EQ(mip.kinds["device_solution"], r.poses);
}

}  // namespace
}  // namespace navfuse::apps

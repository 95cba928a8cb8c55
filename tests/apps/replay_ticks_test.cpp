// End-to-end wheel ticks (issue 17): a simulated VN-300 drive with its odometer written as a
// FusionEngine vehicle tick counter (navfuse sim --wheel-ticks 0.02), replayed with
// wheel.m_per_tick set: the ticks are decoded, fused, and hold the wheel-speed goal over the
// 30 s GNSS outage (0.2 % of 600 m). Without the scale they are rejected as "no_scale".
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "apps/replay/replay.hpp"
#include "apps/simcmd/sim_command.hpp"
#include "simulated_drive.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

class ReplayTicks : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::scratch_dir();
    SimOptions o = testing::short_drive_sim(dir_, "ticks.p1log");
    o.wheel_tick_m = 0.02;
    run_sim(o);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // The demo VN-300 config (the simulated vehicle), with `wheel_extra` added to its wheel section.
  ReplayOptions options(const std::string& wheel_extra) {
    std::ifstream in(std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/vn300.yaml");
    std::stringstream text;
    text << in.rdbuf();
    std::string yaml = text.str();
    yaml.replace(yaml.find("wheel:\n"), 7, "wheel:\n" + wheel_extra);
    testing::write_text(dir_ / "config.yaml", yaml);
    ReplayOptions r;
    r.config_path = (dir_ / "config.yaml").string();
    r.inputs = {(dir_ / "vn.bin").string(), (dir_ / "ticks.p1log").string()};
    r.truth_path = (dir_ / "truth.csv").string();
    return r;
  }
  std::filesystem::path dir_;
};

TEST_F(ReplayTicks, VehicleTicksAreFusedAndHoldTheOutageGoal) {
  const ReplayResult r = run_replay(options("  m_per_tick: 0.02\n"));
  const auto& ticks = r.summary.kinds[static_cast<std::size_t>(MeasurementKind::kWheelTicks)];
  const auto& speed = r.summary.kinds[static_cast<std::size_t>(MeasurementKind::kVehicleSpeed)];
  const auto& acc = r.summary.extra.at("accuracy");
  const double outage_max = acc["gnss_outage"]["horizontal_m"]["max"].get<double>();
  std::printf("ticks decoded %llu used %llu; outage max %.3f m, horizontal RMS %.3f m\n",
              static_cast<unsigned long long>(ticks.decoded), static_cast<unsigned long long>(ticks.used), outage_max,
              acc["horizontal_m"]["rms"].get<double>());
  EXPECT_GT(ticks.used, 5000u);
  EXPECT_EQ(speed.decoded, 0u);  // the odometer is ticks only
  EXPECT_LE(outage_max, 0.002 * 600.0);
}

TEST_F(ReplayTicks, WithoutTheScaleTicksAreRejectedAsNoScale) {
  const ReplayResult r = run_replay(options(""));
  const auto& ticks = r.summary.kinds[static_cast<std::size_t>(MeasurementKind::kWheelTicks)];
  EXPECT_EQ(ticks.used, 0u);
  ASSERT_EQ(ticks.rejected.count("no_scale"), 1u);
  EXPECT_EQ(ticks.rejected.at("no_scale"), ticks.decoded);
}

}  // namespace
}  // namespace navfuse::apps

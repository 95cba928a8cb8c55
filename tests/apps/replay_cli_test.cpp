// `navfuse sim` writes logs the decoders read back with the right counts, and `navfuse replay`
// refuses bad input with a one-line message naming the problem and leaves no output behind.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "apps/common/frontend_registry.hpp"
#include "apps/simcmd/sim_command.hpp"
#include "cli_runner.hpp"
#include "decode_counts.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

using testing::decode_file;
using testing::read_bytes;
using testing::run_cli;
using testing::scratch_dir;
using testing::write_text;

// static_start: 60 s at 200 Hz IMU, 5 Hz GNSS, 50 Hz vehicle speed (apps/sim/scenarios.hpp).
constexpr std::uint64_t kImuSamples = 60 * 200;

class SimFormat : public ::testing::TestWithParam<const char*> {};

TEST_P(SimFormat, DecodeReadsBackWhatSimWrote) {
  const auto dir = scratch_dir();
  const std::string format = GetParam();
  SimOptions o;
  o.scenario = "static_start";
  o.format = format;
  o.out_path = (dir / "log.bin").string();
  o.truth_path = (dir / "truth.csv").string();
  const SimReport report = run_sim(o);
  auto decoded = decode_file(*find_frontend(format), dir / "log.bin");
  EXPECT_EQ(decoded.counters.bad_frames, 0u);
  EXPECT_EQ(decoded.counters.skipped_bytes, 0u);
  EXPECT_EQ(report.written.at("imu"), kImuSamples);
  EXPECT_EQ(decoded.kinds.at("imu"), kImuSamples);
  // 5 Hz fixes over 60 s: 300 on the grid, give or take the one at the boundary.
  EXPECT_NEAR(static_cast<double>(decoded.kinds.at("gnss_position")), 300.0, 1.0);
  for (const auto& [kind, n] : report.written) {
    // The UM220 decoder emits a device solution from each of NAVPOS and NAVATT (one solution is
    // written as both sentences), so it reads back at least as many.
    if (format == "unicore" && kind == "device_solution") {
      EXPECT_GE(decoded.kinds[kind], n);
      continue;
    }
    EXPECT_EQ(decoded.kinds[kind], n) << format << " " << kind;
  }
  EXPECT_GT(report.written.at("device_solution"), 0u);
  EXPECT_EQ(report.truth_rows, kImuSamples);
}

INSTANTIATE_TEST_SUITE_P(AllFormats, SimFormat, ::testing::Values("vn", "mip", "fe", "unicore"));

TEST(SimCommand, WheelOutGoesToAFusionEngineLog) {
  const auto dir = scratch_dir();
  const auto r = run_cli({"sim", "--scenario", "static_start", "--format", "vn", "--out", (dir / "vn.bin").string(),
                          "--wheel-out", (dir / "wheel.p1log").string(), "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto vn = decode_file(*find_frontend("vn"), dir / "vn.bin");
  const auto wheel = decode_file(*find_frontend("fe"), dir / "wheel.p1log");
  EXPECT_EQ(vn.kinds.count("vehicle_speed"), 0u);
  EXPECT_NEAR(static_cast<double>(wheel.kinds.at("vehicle_speed")), 60.0 * 50.0, 1.0);
  EXPECT_EQ(wheel.kinds.size(), 1u);
}

TEST(SimCommand, NonSlipPointMovesTheTruthOnlyWhenTheVehicleTurns) {
  // The IMU's truth changes with where the vehicle does not slip only through rotation
  // (v = v_P - C_nb (omega x l), apps/sim/trajectory.hpp): standing still it is the same truth.
  const auto dir = scratch_dir();
  auto truth_of = [&](const std::string& scenario, const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args{"sim", "--scenario", scenario, "--format", "vn", "--out", (dir / (name + ".vnb")).string(),
                                  "--truth", (dir / (name + ".csv")).string(), "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 0) << r.error;
    std::ifstream in(dir / (name + ".csv"));
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(truth_of("static_start", "s0", {}), truth_of("static_start", "s1", {"--nonslip-point=-1.2,0,0.3"}));
  EXPECT_NE(truth_of("drive_short", "d0", {}), truth_of("drive_short", "d1", {"--nonslip-point=-1.2,0,0.3"}));

  for (const std::string bad : {"--nonslip-point=1,2", "--nonslip-point=nan,0,0"}) {
    const auto r = run_cli({"sim", "--scenario", "static_start", "--format", "vn", "--out", (dir / "bad.vnb").string(), bad});
    EXPECT_NE(r.exit_code, 0) << bad;
    EXPECT_NE(r.error.find("nonslip-point"), std::string::npos) << r.error;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.vnb"));
  }
}

TEST(SimCommand, UnknownScenarioNamesIt) {
  const auto dir = scratch_dir();
  const auto r = run_cli({"sim", "--scenario", "moon_walk", "--format", "vn", "--out", (dir / "x").string()});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.error.find("moon_walk"), std::string::npos) << r.error;
  EXPECT_FALSE(std::filesystem::exists(dir / "x"));
}

class ReplayBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir();
    log_ = dir_ / "vn.bin";
    const auto r = run_cli({"sim", "--scenario", "static_start", "--format", "vn", "--out", log_.string(), "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << r.error;
    out_ = dir_ / "out.p1log";
  }
  // Runs replay with --fe-out and checks the failure: non-zero, one line naming `needle`, and no
  // output file, complete-looking or partial.
  void expect_failure(std::vector<std::string> args, const std::string& needle) {
    args.insert(args.begin(), "replay");
    args.push_back("--fe-out");
    args.push_back(out_.string());
    args.push_back("--quiet");
    const auto r = run_cli(args);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.error.find(needle), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
    EXPECT_FALSE(std::filesystem::exists(out_));
    EXPECT_FALSE(std::filesystem::exists(out_.string() + ".partial"));
  }
  std::filesystem::path dir_, log_, out_;
};

TEST_F(ReplayBadInput, UnknownFormat) { expect_failure({"xyz:" + log_.string()}, "xyz"); }

TEST_F(ReplayBadInput, MissingFile) { expect_failure({(dir_ / "absent.bin").string()}, "absent.bin"); }

TEST_F(ReplayBadInput, UndetectableBytes) {
  std::string noise(4096, '\0');
  for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = static_cast<char>((i * 7919u) % 251u);
  write_text(dir_ / "noise.bin", noise);
  expect_failure({(dir_ / "noise.bin").string()}, "noise.bin");
}

TEST_F(ReplayBadInput, TruncatedFile) {
  auto bytes = read_bytes(log_);
  bytes.resize(bytes.size() - 7);
  std::ofstream(dir_ / "cut.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  expect_failure({"vn:" + (dir_ / "cut.bin").string()}, "cut.bin");
}

TEST_F(ReplayBadInput, BadConfigKey) {
  write_text(dir_ / "bad.yaml", "imu:\n  gyro_arw_deg_rthr_typo: 0.1\n");
  expect_failure({"--config", (dir_ / "bad.yaml").string(), log_.string()}, "gyro_arw_deg_rthr_typo");
}

TEST_F(ReplayBadInput, GoodInputSucceedsAndWritesTheOutput) {
  // static_start never has a heading, so none of its poses is in navigation: exit 2 unless
  // --allow-empty (issue 15, exit codes); the output is written either way.
  const auto refused = run_cli({"replay", log_.string(), "--fe-out", out_.string(), "--quiet"});
  EXPECT_EQ(refused.exit_code, 2) << refused.error;
  EXPECT_NE(refused.error.find("poses written is in navigation"), std::string::npos) << refused.error;
  std::filesystem::remove(out_);
  const auto r = run_cli({"replay", log_.string(), "--fe-out", out_.string(), "--quiet", "--allow-empty"});
  EXPECT_EQ(r.exit_code, 0) << r.error;
  EXPECT_TRUE(std::filesystem::exists(out_));
  EXPECT_FALSE(std::filesystem::exists(out_.string() + ".partial"));
}

}  // namespace
}  // namespace navfuse::apps

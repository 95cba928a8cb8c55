// `navfuse replay` exits non-zero (2) with a one-line reason when it produced nothing useful, warns
// when part of a log was skipped for going back in time, and never prints an accuracy table of
// zeros for a run that had no pose to score (issue 15, item 9).
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "apps/replay/replay.hpp"
#include "cli_runner.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

using testing::read_bytes;
using testing::run_cli;
using testing::scratch_dir;

// static_start: 60 s at 200 Hz IMU (apps/sim/scenarios.hpp); the filter levels after 1 s
// stationary (FilterOptions::level_time_s).
constexpr std::uint64_t kImuSamples = 60 * 200;

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

class ReplayExitCode : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir();
    log_ = dir_ / "vn.bin";
    truth_ = dir_ / "truth.csv";
    const auto r = run_cli({"sim", "--scenario", "static_start", "--format", "vn", "--out", log_.string(), "--truth",
                            truth_.string(), "--wheel-out", (dir_ / "wheel.p1log").string(), "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << r.error;
  }
  // Replays `args` and expects exit 2 with a one-line error containing `needle`.
  void expect_useless(std::vector<std::string> args, const std::string& needle) {
    args.insert(args.begin(), "replay");
    args.push_back("--quiet");
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << r.error;
    EXPECT_NE(r.error.find(needle), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
  }
  std::filesystem::path dir_, log_, truth_;
};

TEST_F(ReplayExitCode, WrongFormatPrefixDecodesNothing) {
  expect_useless({"mip:" + log_.string()}, "no frame decoded from mip:" + log_.string());
}

TEST_F(ReplayExitCode, LogWithoutImu) {
  // The wheel log holds vehicle speed only: frames decode, but there is nothing to navigate with.
  expect_useless({"fe:" + (dir_ / "wheel.p1log").string()}, "no IMU sample");
}

TEST_F(ReplayExitCode, FilterNeverLeavesInitialization) {
  // 1/240 of 60 s = 0.25 s of log: less than the 1 s of stationary data levelling needs.
  auto bytes = read_bytes(log_);
  bytes.resize(bytes.size() / 240);
  write_bytes(dir_ / "short.bin", bytes);
  const std::string input = "vn:" + (dir_ / "short.bin").string();
  expect_useless({input, "--allow-truncated"}, "never left initialization");

  ReplayOptions o;
  o.inputs = {input};
  o.allow_truncated = true;
  o.truth_path = truth_.string();
  const ReplayResult result = run_replay(o);
  EXPECT_GT(result.imu_samples, 0u);
  EXPECT_NE(result.failure.find("never left initialization"), std::string::npos) << result.failure;
  EXPECT_NE(result.accuracy_text.find("no poses in navigation to score"), std::string::npos) << result.accuracy_text;
  EXPECT_EQ(result.accuracy_text.find("0.000"), std::string::npos) << result.accuracy_text;
}

TEST_F(ReplayExitCode, StationaryLogWithoutNavigationSaysSoInsteadOfZeros) {
  // static_start levels (a useful attitude, exit 0) but never has a heading to navigate with.
  ReplayOptions o;
  o.inputs = {log_.string()};
  o.truth_path = truth_.string();
  const ReplayResult result = run_replay(o);
  EXPECT_EQ(result.failure, "");
  EXPECT_EQ(result.accuracy_text, "accuracy against csv reference at the IMU: no poses in navigation to score\n");
  EXPECT_EQ(run_cli({"replay", log_.string(), "--quiet"}).exit_code, 0);
}

TEST(ReplayExitCodeDemo, NavigatingLogSucceedsAndScoresPoses) {
  const std::string demo = std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/";
  ReplayOptions o;
  o.inputs = {demo + "vn300.vnb"};
  o.config_path = demo + "vn300.yaml";
  o.truth_path = demo + "truth.csv";
  const ReplayResult result = run_replay(o);
  EXPECT_EQ(result.failure, "");
  EXPECT_EQ(result.imu_time_backwards, 0u);
  EXPECT_EQ(result.accuracy_text.find("no poses"), std::string::npos) << result.accuracy_text;
  EXPECT_NE(result.accuracy_text.find("horizontal_m"), std::string::npos) << result.accuracy_text;
}

TEST_F(ReplayExitCode, LogConcatenatedWithItselfWarnsWithTheCount) {
  auto bytes = read_bytes(log_);
  const auto half = bytes;
  bytes.insert(bytes.end(), half.begin(), half.end());
  write_bytes(dir_ / "twice.bin", bytes);

  ReplayOptions o;
  o.inputs = {"vn:" + (dir_ / "twice.bin").string()};
  const ReplayResult result = run_replay(o);
  EXPECT_EQ(result.failure, "");
  // Every IMU sample of the second copy is dated before the last one of the first.
  EXPECT_EQ(result.imu_time_backwards, kImuSamples);

  ::testing::internal::CaptureStderr();
  const auto r = run_cli({"replay", "vn:" + (dir_ / "twice.bin").string(), "--quiet"});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(r.exit_code, 0) << r.error;
  EXPECT_NE(err.find("warning: " + std::to_string(kImuSamples) + " IMU samples rejected as time_backwards"),
            std::string::npos)
      << err;
}

}  // namespace
}  // namespace navfuse::apps

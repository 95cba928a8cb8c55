// `navfuse run` with bad arguments: each fails before starting, with a one-line error that names
// the problem, and a non-zero exit (DESIGN.md "non-zero with a one-line reason").
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "tests/integration/child_process.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

class RunErrorsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir();
    config_ = write_file(dir_ / "ok.yaml", "device: vn300\noutput:\n  rate_hz: 50\n");
    log_ = write_file(dir_ / "log.bin", std::string(64, '\0'));
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Runs `navfuse run ARGS...`; expects failure with exactly one line naming every `needles`.
  void expect_one_line_error(std::vector<std::string> args, const std::vector<std::string>& needles) {
    args.insert(args.begin(), {navfuse_binary(), "run"});
    const RunResult r = run_to_exit(args, (dir_ / "out.txt").string());
    EXPECT_NE(r.exit_code, 0) << r.output;
    EXPECT_NE(r.exit_code, -1) << "did not exit: " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(r.output.rfind("navfuse: error: ", 0), 0u) << r.output;
    for (const std::string& n : needles) EXPECT_NE(r.output.find(n), std::string::npos) << "no '" << n << "' in: " << r.output;
  }

  std::filesystem::path dir_;
  std::string config_;
  std::string log_;
};

TEST_F(RunErrorsTest, UnknownFormat) {
  expect_one_line_error({"--config", config_, "--in", "novatel:file:" + log_}, {"novatel", "unknown input format"});
}

TEST_F(RunErrorsTest, MissingInputFile) {
  const std::string missing = (dir_ / "no_such_log.bin").string();
  expect_one_line_error({"--config", config_, "--in", "vn:file:" + missing}, {missing});
}

TEST_F(RunErrorsTest, MissingSerialDevice) {
  const std::string missing = (dir_ / "ttyUSB9").string();
  expect_one_line_error({"--config", config_, "--in", "vn:serial:" + missing + "?baud=921600"}, {missing});
}

TEST_F(RunErrorsTest, BadConfigKey) {
  const std::string bad = write_file(dir_ / "bad.yaml", "imu:\n  gyro_arw_deg_rthr: 0.1\n  gyro_noise: 3\n");
  expect_one_line_error({"--config", bad, "--in", "vn:file:" + log_}, {"imu.gyro_noise"});
}

TEST_F(RunErrorsTest, MissingConfigFile) {
  const std::string missing = (dir_ / "nope.yaml").string();
  expect_one_line_error({"--config", missing, "--in", "vn:file:" + log_}, {missing});
}

TEST_F(RunErrorsTest, BadInputUri) {
  expect_one_line_error({"--config", config_, "--in", "vn:tcp://localhost"}, {"tcp://localhost", "PORT"});
}

TEST_F(RunErrorsTest, BadOutputUri) {
  expect_one_line_error({"--config", config_, "--in", "vn:file:" + log_, "--fe-out", "tcp-listen://:99999"},
                        {"--fe-out", "99999"});
}

TEST_F(RunErrorsTest, UnknownUriScheme) {
  expect_one_line_error({"--config", config_, "--in", "vn:ftp://host/x"}, {"ftp"});
}

TEST_F(RunErrorsTest, ConfigureDeviceNeedsTheFormat) {
  expect_one_line_error({"--config", config_, "--in", "tcp://127.0.0.1:9", "--configure-device"},
                        {"--configure-device", "FORMAT"});
}

}  // namespace
}  // namespace navfuse::test

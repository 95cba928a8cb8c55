// `navfuse decode` end to end, through the real executable: for each protocol, a stream written
// by that front-end's encoder from simulated measurements is detected without a FORMAT: prefix,
// and --summary-json reports exactly the frames, byte counts and measurements by kind that were
// written. Also the one-line errors for bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/common/frontend_registry.hpp"
#include "apps/sim/scenarios.hpp"
#include "apps/sim/simulator.hpp"

namespace navfuse::apps {
namespace {

struct RunResult {
  int exit_code;
  std::string stderr_text;
};

RunResult run_navfuse(const std::string& args) {
  const std::string err = ::testing::TempDir() + "/decode_stderr.txt";
  const std::string cmd = std::string(NAVFUSE_EXE) + " " + args + " > /dev/null 2> " + err;
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

// A few seconds of a simulated drive: IMU, GNSS, wheel speed, plus a device solution per IMU
// sample made from truth (what a device INS would report).
std::vector<Measurement> sample_measurements() {
  sim::Scenario sc = sim::make_scenario("drive_short");
  sim::Simulator s(sc);
  std::vector<Measurement> out;
  Measurement m;
  while (s.next(m) && out.size() < 3000) {
    out.push_back(m);
    if (kind_of(m) == MeasurementKind::kImu && out.size() % 20 == 0) {
      const auto& t = s.truth();
      NavSolution sol;
      sol.header = header_of(m);
      sol.mode = NavMode::kNavigation;
      sol.gnss_fix = GnssFixType::kFix3D;
      sol.lat_rad = t.llh.lat_rad;
      sol.lon_rad = t.llh.lon_rad;
      sol.height_m = t.llh.height_m;
      sol.vel_ned_mps = t.vel_ned_mps;
      sol.q_nb = t.q_nb;
      sol.rpy_rad = t.rpy_rad;
      sol.pos_std_ned_m = {1.0, 1.0, 2.0};
      sol.vel_std_ned_mps = {0.1, 0.1, 0.2};
      sol.att_std_rpy_rad = {0.01, 0.01, 0.02};
      sol.header.valid = NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
                         NavSolution::kValidPositionStd | NavSolution::kValidVelocityStd |
                         NavSolution::kValidAttitudeStd | NavSolution::kValidHeading;
      out.push_back(sol);
    }
  }
  return out;
}

class DecodeCli : public ::testing::TestWithParam<std::string> {};

TEST_P(DecodeCli, DetectsFormatAndCountsWhatWasWritten) {
  const frontends::FrontendInfo* fe = find_frontend(GetParam());
  ASSERT_NE(fe, nullptr);
  auto encoder = fe->make_encoder();
  std::vector<std::uint8_t> bytes;
  std::map<std::string, std::uint64_t> encoded;
  for (const auto& m : sample_measurements()) {
    if (encoder->encode(m, bytes)) ++encoded[std::string(to_string(kind_of(m)))];
  }
  ASSERT_FALSE(bytes.empty());
  ASSERT_GT(encoded["imu"], 0u) << GetParam();

  const std::string dir = ::testing::TempDir();
  const std::string log = dir + "/decode_cli." + GetParam();
  const std::string summary = dir + "/decode_cli_" + GetParam() + ".json";
  std::ofstream(log, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                             static_cast<std::streamsize>(bytes.size()));
  const RunResult r = run_navfuse("decode " + log + " --format jsonl --summary-json " + summary);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;

  const auto j = nlohmann::json::parse(std::ifstream(summary));
  ASSERT_EQ(j["inputs"].size(), 1u);
  const auto& in = j["inputs"][0];
  EXPECT_EQ(in["format"], GetParam()) << "detected without a prefix";
  EXPECT_EQ(in["bytes"], bytes.size());
  EXPECT_EQ(in["bad_frames"], 0);
  EXPECT_EQ(in["skipped_bytes"], 0);
  EXPECT_GT(in["frames"].get<std::uint64_t>(), 0u);
  // Kinds that a protocol carries one-to-one must come back exactly as written.
  for (const char* kind : {"imu", "gnss_position", "gnss_velocity", "device_solution"}) {
    if (encoded.count(kind) == 0) continue;
    const auto decoded = j["measurements"][kind]["decoded"].get<std::uint64_t>();
    if (GetParam() == "unicore" && std::string(kind) == "device_solution") {
      // The UM220 has a single navigation output: NAVPOS/NAVVEL written for a GNSS fix are also
      // the module's own solution (Unicore digest §4.5), so more device solutions come back.
      EXPECT_GE(decoded, encoded[kind]) << kind;
    } else {
      EXPECT_EQ(decoded, encoded[kind]) << GetParam() << " " << kind;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllFrontends, DecodeCli, ::testing::Values("fe", "mip", "vn", "unicore"));

TEST(DecodeCliErrors, OneLineErrorsAndNonZeroExit) {
  const std::string dir = ::testing::TempDir();
  RunResult r = run_navfuse("decode " + dir + "/does_not_exist.bin");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.stderr_text.find("does_not_exist.bin"), std::string::npos) << r.stderr_text;
  EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;

  const std::string junk = dir + "/junk.bin";
  std::ofstream(junk) << "this is not any navigation protocol at all\n";
  r = run_navfuse("decode " + junk);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.stderr_text.find("cannot detect the format"), std::string::npos) << r.stderr_text;

  r = run_navfuse("decode xyz:" + junk);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.stderr_text.find("unknown input format 'xyz'"), std::string::npos) << r.stderr_text;

  const std::string empty = dir + "/empty.bin";
  std::ofstream(empty).close();
  r = run_navfuse("decode mip:" + empty);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.stderr_text.find("empty"), std::string::npos) << r.stderr_text;
}

TEST(DecodeCliErrors, TruncatedFileIsCountedNotFatal) {
  // A log cut mid-frame decodes what is complete and counts the tail as skipped.
  const frontends::FrontendInfo* fe = find_frontend("mip");
  auto encoder = fe->make_encoder();
  std::vector<std::uint8_t> bytes;
  const auto ms = sample_measurements();
  std::size_t frames_written = 0;
  for (std::size_t i = 0; i < 50; ++i) {
    if (kind_of(ms[i]) == MeasurementKind::kImu && encoder->encode(ms[i], bytes)) ++frames_written;
  }
  ASSERT_GT(frames_written, 2u);
  bytes.resize(bytes.size() - 5);
  const std::string log = ::testing::TempDir() + "/truncated.mip";
  const std::string summary = ::testing::TempDir() + "/truncated.json";
  std::ofstream(log, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                             static_cast<std::streamsize>(bytes.size()));
  const RunResult r = run_navfuse("decode " + log + " --summary-json " + summary);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto j = nlohmann::json::parse(std::ifstream(summary));
  EXPECT_EQ(j["measurements"]["imu"]["decoded"].get<std::uint64_t>(), frames_written - 1);
  EXPECT_GT(j["inputs"][0]["skipped_bytes"].get<std::uint64_t>(), 0u);
}

}  // namespace
}  // namespace navfuse::apps

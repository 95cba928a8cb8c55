// `navfuse run --csv FILE --nmea-out URI` (issue 17): the CSV of replay --csv, written by the same
// writer, and NMEA GGA/RMC/HDT on an output link, here a file. The demo VN-300 log is fed as a
// file input; run ends when it has been read.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/integration/child_process.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

std::string demo(const std::string& name) { return std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/" + name; }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// NMEA 0183: "$" body "*" two upper-case hex digits of the XOR of the body's characters, CR LF.
bool valid_sentence(const std::string& line) {
  if (line.size() < 6 || line.front() != '$' || line.back() != '\r') return false;
  const std::size_t star = line.rfind('*');
  if (star == std::string::npos || star + 4 != line.size()) return false;
  unsigned x = 0;
  for (std::size_t i = 1; i < star; ++i) x ^= static_cast<unsigned char>(line[i]);
  char hex[3];
  std::snprintf(hex, sizeof hex, "%02X", x);
  return line.compare(star + 1, 2, hex) == 0;
}

TEST(RunFileOutputs, CsvAsReplayAndNmeaSentences) {
  const auto dir = scratch_dir();
  const std::string csv = (dir / "run.csv").string();
  const std::string nmea = (dir / "run.nmea").string();
  const std::string replay_csv = (dir / "replay.csv").string();
  const RunResult r = run_to_exit({navfuse_binary(), "run", "--config", demo("vn300.yaml"), "--in",
                                   "vn:file:" + demo("vn300.vnb"), "--csv", csv, "--nmea-out", "file:" + nmea, "--quiet"},
                                  (dir / "run.txt").string(), 60000);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const RunResult rp = run_to_exit({navfuse_binary(), "replay", "--config", demo("vn300.yaml"), demo("vn300.vnb"),
                                    "--csv", replay_csv, "--quiet"},
                                   (dir / "replay.txt").string(), 60000);
  ASSERT_EQ(rp.exit_code, 0) << rp.output;

  // Same header, one row per pose: the 190 s log at output.rate_hz (the replay's row count, up
  // to the measurements a live run may drop when its queue overflows).
  const std::vector<std::string> run_rows = lines_of(read_text_file(csv));
  const std::vector<std::string> replay_rows = lines_of(read_text_file(replay_csv));
  ASSERT_GT(replay_rows.size(), 1000u);
  ASSERT_FALSE(run_rows.empty());
  EXPECT_EQ(run_rows.front(), replay_rows.front());
  EXPECT_GT(run_rows.size(), replay_rows.size() * 9 / 10);
  EXPECT_LE(run_rows.size(), replay_rows.size());

  // Every line a sentence with a right checksum; GGA and RMC at most 10 Hz over the 190 s log
  // (fewer: a link's thread drops epochs rather than hold the filter back, and a file input is
  // read far faster than real time), HDT once the heading is known.
  std::size_t gga = 0, rmc = 0, hdt = 0, fixed = 0;
  for (const std::string& line : lines_of(read_text_file(nmea))) {
    EXPECT_TRUE(valid_sentence(line)) << line;
    if (line.rfind("$GNGGA,", 0) == 0) {
      ++gga;
      if (line.find(",1,") != std::string::npos || line.find(",6,") != std::string::npos) ++fixed;
    }
    if (line.rfind("$GNRMC,", 0) == 0) ++rmc;
    if (line.rfind("$GNHDT,", 0) == 0) ++hdt;
  }
  std::printf("run: %zu CSV rows (replay %zu); NMEA %zu GGA (%zu with a position), %zu RMC, %zu HDT\n",
              run_rows.size() - 1, replay_rows.size() - 1, gga, fixed, rmc, hdt);
  EXPECT_GT(gga, 100u);
  EXPECT_LE(gga, 1901u);
  EXPECT_EQ(rmc, gga);
  EXPECT_GT(hdt, gga / 2);
  EXPECT_LE(hdt, gga);
  EXPECT_GT(fixed, gga / 2);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace navfuse::test

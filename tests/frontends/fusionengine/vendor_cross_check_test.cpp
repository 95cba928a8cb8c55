// navfuse's framer against Point One's own (fusion-engine-client's FusionEngineDecoder, through
// fe_vendor_count.py): the same valid frames per message type on the real capture and on a
// corrupted stream. The two framers are written independently from the spec (§2.3-2.4) and
// agree on every rule that decides a frame: sync, zero reserved bytes, CRC-32 over the frame,
// resync one byte after a failed candidate. Skips when no python3 can import the client (it is
// never installed by the tests: NAVFUSE_FE_PYTHON names one that can, and the virtualenv the
// fe_python_client_compat test creates in the build tree is tried too) or without the capture.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "test_support.hpp"
#include "tests/bench/fusionengine_bench_stream.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

using TypeCounts = std::map<unsigned, std::uint64_t>;

TypeCounts navfuse_counts(std::span<const std::uint8_t> bytes) {
  TypeCounts counts;
  for (const auto& f : test::frames_of(bytes)) ++counts[f.header.message_type];
  return counts;
}

struct VendorRun {
  bool skipped = true;
  TypeCounts counts;
  std::string output;
};

// Runs fe_vendor_count.py with the first interpreter that can import the client. Its decoder is
// given navfuse's bound for unknown types (64 KiB) as max_payload_len_bytes and flushed at the
// end, so that neither framer stops early on a corrupted size (see the script's usage).
VendorRun vendor_counts(const std::filesystem::path& file) {
  std::vector<std::string> pythons;
  if (const char* env = std::getenv("NAVFUSE_FE_PYTHON")) pythons.emplace_back(env);
  const std::string venv = std::string(NAVFUSE_BINARY_DIR) + "/tests/frontends/fusionengine/fe_python_venv/bin/python";
  if (std::filesystem::exists(venv)) pythons.push_back(venv);
  pythons.emplace_back("python3");
  const std::string script = std::string(NAVFUSE_SOURCE_DIR) + "/tests/frontends/fusionengine/fe_vendor_count.py";
  VendorRun run;
  for (const std::string& py : pythons) {
    const std::string cmd = "'" + py + "' '" + script + "' '" + file.string() + "' --max-payload " +
                            std::to_string(kMaxUnknownPayloadSize) + " --flush 2>&1";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (pipe == nullptr) continue;
    std::string out;
    char buf[4096];
    while (std::fgets(buf, sizeof buf, pipe) != nullptr) out += buf;
    const int status = pclose(pipe);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 3) continue;  // this python lacks the client
    run.skipped = false;
    run.output = out;
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << py << ":\n" << out;
    std::istringstream lines(out);
    std::string word;
    unsigned type = 0;
    std::uint64_t n = 0;
    for (std::string line; std::getline(lines, line);) {
      std::istringstream fields(line);
      if (fields >> word >> type >> n && word == "type") run.counts[type] = n;
    }
    return run;
  }
  return run;
}

std::filesystem::path scratch_file(const std::string& test_name, std::span<const std::uint8_t> bytes) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("navfuse_" + test_name + "_" + std::to_string(::getpid()) + ".p1log");
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return path;
}

TEST(FeVendorCrossCheck, RealCaptureSameFramesPerType) {
  const std::string capture = std::string(NAVFUSE_SHARED_DIR) + "/captures/fe_example_data.p1log";
  const auto bytes = test::read_file(capture);
  if (!bytes) GTEST_SKIP() << "capture not present";
  const VendorRun vendor = vendor_counts(capture);
  if (vendor.skipped) GTEST_SKIP() << "no python3 with fusion_engine_client (set NAVFUSE_FE_PYTHON)";
  // The shared captures' README, counted by an independent framer: Pose 2, GNSSInfo 1,
  // GNSSSatellite 1.
  const TypeCounts expected{{10000, 2}, {10001, 1}, {10002, 1}};
  EXPECT_EQ(navfuse_counts(*bytes), expected);
  EXPECT_EQ(vendor.counts, expected) << vendor.output;
}

TEST(FeVendorCrossCheck, CorruptedStreamSameFramesPerType) {
  // The benchmark stream with GNSSSignals, 4,000 IMU samples (~0.6 MB: the client's Python
  // framer runs at about 1 MB/s on corrupted bytes), 1 % of its bytes corrupted.
  const std::vector<std::uint8_t> bytes = bench::fe_bench_stream(0.01, true, 0, 4'000);
  const auto file = scratch_file("FeVendorCrossCheck_Corrupted", bytes);
  const VendorRun vendor = vendor_counts(file);
  std::filesystem::remove(file);
  if (vendor.skipped) GTEST_SKIP() << "no python3 with fusion_engine_client (set NAVFUSE_FE_PYTHON)";
  const TypeCounts ours = navfuse_counts(bytes);
  // Pose (10000) and IMUOutput (11000) frames survive (a ~1 kB GNSSSignals frame seldom does),
  // and corruption must have cost frames, or the check shows nothing.
  ASSERT_EQ(ours.count(10000), 1u);
  ASSERT_EQ(ours.count(11000), 1u);
  EXPECT_LT(ours.at(11000), 4'000u);
  EXPECT_GT(ours.at(11000), 500u);
  EXPECT_EQ(vendor.counts, ours) << vendor.output;
}

}  // namespace
}  // namespace navfuse::frontends::fusionengine

// "Counts add up" (issue 15): for every measurement kind, what was decoded is used, rejected for
// a named reason, or still held at the end of the log, exactly once:
//   decoded = used + sum(rejected by reason) + pending_at_end
// checked on the summary JSON of every demo log and of faulty logs made from them (1 % of bytes
// corrupted, which hits every reason path: bad frames, wild times, time gaps, gates; a log
// concatenated with itself; a GNSS-and-wheel log without IMU, where everything waits).
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "apps/replay/replay.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

const std::string kDemo = std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/";

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// Every kind of the summary adds up; returns the total decoded (so a test cannot pass on an empty
// summary).
std::uint64_t expect_counts_add_up(const std::string& input, const std::string& config) {
  SCOPED_TRACE(input);
  ReplayOptions o;
  o.inputs = {input};
  o.config_path = config;
  o.allow_truncated = true;  // a corrupted length near the end looks like a cut frame
  const nlohmann::ordered_json j = run_replay(o).summary.to_json(/*decode_only=*/false);
  std::uint64_t total = 0;
  for (const auto& [kind, c] : j["measurements"].items()) {
    std::uint64_t rejected = 0;
    for (const auto& [reason, n] : c["rejected"].items()) rejected += n.get<std::uint64_t>();
    const auto decoded = c["decoded"].get<std::uint64_t>();
    EXPECT_EQ(decoded, c["used"].get<std::uint64_t>() + rejected + c["pending_at_end"].get<std::uint64_t>())
        << kind << ": " << c.dump();
    total += decoded;
  }
  return total;
}

struct DemoLog {
  const char* file;
  const char* config;
};
const DemoLog kLogs[] = {{"vn300.vnb", "vn300.yaml"}, {"cv7.mip", "cv7.yaml"}, {"um220.log", "um220.yaml"},
                         {"atlas.p1log", "fusionengine.yaml"}};

TEST(CountsAddUp, EveryDemoLog) {
  for (const DemoLog& log : kLogs) EXPECT_GT(expect_counts_add_up(kDemo + log.file, kDemo + log.config), 1000u);
}

// The non-holonomic constraint (the demo configs are a land vehicle's): every update tried is
// applied or gated, and the summary says how many of each.
TEST(CountsAddUp, TheConstraintsUpdatesAreAppliedOrGated) {
  for (const DemoLog& log : kLogs) {
    SCOPED_TRACE(log.file);
    ReplayOptions o;
    o.inputs = {kDemo + log.file};
    o.config_path = kDemo + log.config;
    const nlohmann::ordered_json j = run_replay(o).summary.to_json(/*decode_only=*/false);
    ASSERT_TRUE(j.contains("constraints")) << j.dump();
    const auto& nhc = j["constraints"]["nhc"];
    const auto tried = nhc["count"].get<std::uint64_t>();
    const auto applied = nhc["updates"].get<std::uint64_t>();
    EXPECT_GT(applied, 500u);  // 10 Hz over more than a minute of driving
    const double gated = nhc["fraction_above_gate"].get<double>() * static_cast<double>(tried);
    EXPECT_NEAR(static_cast<double>(applied) + gated, static_cast<double>(tried), 1e-6);
    EXPECT_GT(nhc["mean_nis_per_dim"].get<double>(), 0.0);
  }
}

TEST(CountsAddUp, LogWithoutImuKeepsItsAidingPending) {
  // GNSS and wheel speed only: nothing is fused; what the buffer could not hold is "overflow",
  // the rest is pending at the end, not lost from the counts.
  ReplayOptions o;
  o.inputs = {kDemo + "vn300_wheel.p1log"};
  const auto j = run_replay(o).summary.to_json(false);
  EXPECT_GT(j["measurements"]["vehicle_speed"]["pending_at_end"].get<std::uint64_t>(), 0u);
  EXPECT_GT(expect_counts_add_up(kDemo + "vn300_wheel.p1log", ""), 1000u);
}

TEST(CountsAddUp, CorruptedLogs) {
  const auto dir = testing::scratch_dir();
  for (const DemoLog& log : kLogs) {
    auto bytes = testing::read_bytes(kDemo + log.file);
    std::mt19937_64 rng(15);
    for (std::size_t i = 0; i < bytes.size() / 100; ++i) bytes[rng() % bytes.size()] ^= static_cast<std::uint8_t>(1 + rng() % 255);
    const auto path = dir / log.file;
    write_bytes(path, bytes);
    const std::string format = std::string(log.file) == "vn300.vnb"   ? "vn:"
                               : std::string(log.file) == "cv7.mip"   ? "mip:"
                               : std::string(log.file) == "um220.log" ? "unicore:"
                                                                      : "fe:";
    EXPECT_GT(expect_counts_add_up(format + path.string(), kDemo + log.config), 1000u);
  }
}

TEST(CountsAddUp, LogConcatenatedWithItself) {
  const auto dir = testing::scratch_dir();
  auto bytes = testing::read_bytes(kDemo + "vn300.vnb");
  const auto once = bytes;
  bytes.insert(bytes.end(), once.begin(), once.end());
  write_bytes(dir / "twice.vnb", bytes);
  EXPECT_GT(expect_counts_add_up("vn:" + (dir / "twice.vnb").string(), kDemo + "vn300.yaml"), 1000u);
}

}  // namespace
}  // namespace navfuse::apps

// NAVFUSE_STATUS carries the per-kind innovation statistics as real LCM traffic: `navfuse run` on
// the bundled VN-300 drive publishes its final status when the input ends; its `innovations[]`
// must say, kind by kind, what the same run's --summary-json says (an independent encoder of the
// same counts), and GNSS positions must have been tried; the non-holonomic constraint's are listed
// as kind "nhc", as its constraints.nhc.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <thread>

#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>

#include "navfuse/status_t.hpp"
#include "tests/integration/child_process.hpp"
#include "tests/integration/lcm_receiver.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

constexpr int kTimeoutMs = 60000;
const std::filesystem::path kDemo = std::filesystem::path(NAVFUSE_SOURCE_DIR) / "data/demo";

using RunStatusInnovationsTest = ScratchDirTest;

TEST_F(RunStatusInnovationsTest, FinalStatusHasTheSummaryInnovationStatistics) {
  const std::string url = private_lcm_url(11);
  lcm::LCM rx(url);
  ASSERT_TRUE(rx.good()) << url;
  LcmReceiver<navfuse::status_t> statuses(rx, "NAVFUSE_STATUS");
  std::atomic<bool> stop{false};
  std::thread pump([&] {
    while (!stop.load()) rx.handleTimeout(20);
  });
  const std::string json = (dir_ / "run.json").string();
  const RunResult r = run_to_exit({navfuse_binary(), "run", "--config", (kDemo / "vn300.yaml").string(), "--in",
                                   (kDemo / "vn300.vnb").string(), "--lcm", url, "--summary-json", json, "--quiet"},
                                  (dir_ / "run.log").string(), kTimeoutMs);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the last datagram taken in
  stop = true;
  pump.join();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_FALSE(statuses.messages.empty());
  const navfuse::status_t& last = statuses.messages.back();
  const nlohmann::json summary = nlohmann::json::parse(read_text_file(json));

  ASSERT_EQ(last.num_innovations, static_cast<std::int16_t>(last.innovations.size()));
  int listed_in_summary = 0;
  for (const auto& [kind, m] : summary["measurements"].items()) {
    if (m.contains("innovation")) ++listed_in_summary;
  }
  // The demo is a land vehicle: its non-holonomic constraint is listed too, as kind "nhc".
  ASSERT_TRUE(summary.contains("constraints")) << summary.dump();
  const auto& nhc = summary["constraints"]["nhc"];
  EXPECT_EQ(last.num_innovations, listed_in_summary + 1);
  bool gnss_position = false, nhc_listed = false;
  for (const navfuse::innovation_t& i : last.innovations) {
    SCOPED_TRACE(i.kind);
    if (i.kind == "nhc") {
      nhc_listed = true;
      EXPECT_EQ(i.count, nhc["count"].get<std::int64_t>());
      EXPECT_EQ(i.accepted, nhc["updates"].get<std::int64_t>());
      EXPECT_EQ(i.rejected, i.count - i.accepted);
      EXPECT_GT(i.accepted, 100);  // minutes of driving at 10 Hz
      EXPECT_FLOAT_EQ(i.mean_nis_per_dim, nhc["mean_nis_per_dim"].get<float>());
      EXPECT_FLOAT_EQ(i.fraction_above_gate, nhc["fraction_above_gate"].get<float>());
      continue;
    }
    const auto& m = summary["measurements"][i.kind];
    ASSERT_TRUE(m.contains("innovation")) << m.dump();
    const auto& in = m["innovation"];
    EXPECT_EQ(i.count, in["count"].get<std::int64_t>());
    EXPECT_EQ(i.accepted, m["used"].get<std::int64_t>());
    std::int64_t rejected = 0;
    for (const auto& [reason, n] : m["rejected"].items()) rejected += n.get<std::int64_t>();
    EXPECT_EQ(i.rejected, rejected);
    EXPECT_FLOAT_EQ(i.mean_nis, in["mean_nis"].get<float>());
    EXPECT_FLOAT_EQ(i.mean_nis_per_dim, in["mean_nis_per_dim"].get<float>());
    EXPECT_FLOAT_EQ(i.fraction_above_gate, in["fraction_above_gate"].get<float>());
    if (i.kind == "gnss_position") {
      gnss_position = true;
      EXPECT_GT(i.count, 100);  // the drive fuses its fixes for minutes
    }
  }
  EXPECT_TRUE(gnss_position);
  EXPECT_TRUE(nhc_listed);
}

}  // namespace
}  // namespace navfuse::test

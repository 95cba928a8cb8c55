// End-to-end `navfuse smooth` and `navfuse bench --reference smoothed` on a simulated VN-300
// drive (navfuse sim drive_short: a 30 s GNSS outage at 20 m/s, 95-125 s) with truth. Label
// "scenario". The smoothed solution goes through replay's outputs with mode "smoothed", is
// scored against the simulator's truth beside the forward filter, and is the reference bench
// compares the forward filter and the device with.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "apps/bench/bench.hpp"
#include "apps/common/frontend_registry.hpp"
#include "apps/replay/replay.hpp"
#include "apps/simcmd/sim_command.hpp"
#include "decode_counts.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

class SmoothScenario : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::scratch_dir();
    SimOptions o;
    o.scenario = "drive_short";
    o.format = "vn";
    o.out_path = (dir_ / "vn.bin").string();
    o.truth_path = (dir_ / "truth.csv").string();
    run_sim(o);
  }
  ReplayOptions options(bool smooth) {
    ReplayOptions r;
    r.config_path = std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/vn300.yaml";
    r.inputs = {(dir_ / "vn.bin").string()};
    r.truth_path = (dir_ / "truth.csv").string();
    r.csv_out = (dir_ / (smooth ? "smoothed.csv" : "forward.csv")).string();
    r.fe_out = (dir_ / (smooth ? "smoothed.p1log" : "forward.p1log")).string();
    r.smooth = smooth;
    return r;
  }
  std::filesystem::path dir_;
};

double metric(const nlohmann::ordered_json& accuracy, const char* group, const char* name, const char* stat) {
  const nlohmann::ordered_json& g = group[0] == '\0' ? accuracy : accuracy.at(group);
  return g.at(name).at(stat).get<double>();
}

TEST_F(SmoothScenario, SmoothedBeatsForwardAgainstTruthThroughReplayOutputs) {
  const ReplayResult forward = run_replay(options(false));
  const ReplayResult smoothed = run_replay(options(true));
  ASSERT_TRUE(smoothed.failure.empty()) << smoothed.failure;
  const auto& s = smoothed.summary.extra.at("accuracy");
  const auto& f = smoothed.summary.extra.at("forward_accuracy");
  // The forward pass inside smooth is replay's forward pass: the same score.
  EXPECT_DOUBLE_EQ(metric(f, "", "horizontal_m", "rms"), metric(forward.summary.extra.at("accuracy"), "", "horizontal_m", "rms"));
  const double f_outage = metric(f, "gnss_outage", "horizontal_m", "max");
  const double s_outage = metric(s, "gnss_outage", "horizontal_m", "max");
  std::printf("drive_short 30 s outage, horizontal max: forward %.3f m, smoothed %.3f m; all-time RMS %.3f / %.3f m; "
              "heading RMS %.3f / %.3f deg\n",
              f_outage, s_outage, metric(f, "", "horizontal_m", "rms"), metric(s, "", "horizontal_m", "rms"),
              metric(f, "", "heading_deg", "rms"), metric(s, "", "heading_deg", "rms"));
  EXPECT_LT(s_outage, f_outage);
  EXPECT_LT(metric(s, "", "heading_deg", "rms"), metric(f, "", "heading_deg", "rms"));
  EXPECT_LT(metric(s, "", "velocity_mps", "rms"), metric(f, "", "velocity_mps", "rms"));
  const auto& sm = smoothed.summary.extra.at("smoother");
  EXPECT_GT(sm.at("intervals").get<std::uint64_t>(), 2000u);
  EXPECT_EQ(sm.at("singular_intervals").get<std::uint64_t>(), 0u);
  // Every CSV row is a smoothed one, at the output rate over the forward filter's navigation.
  std::ifstream csv(dir_ / "smoothed.csv");
  std::string line;
  std::getline(csv, line);
  std::size_t rows = 0, smoothed_rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    if (line.find(",smoothed,") != std::string::npos) ++smoothed_rows;
  }
  EXPECT_GT(rows, 15000u);  // ~157 s of navigation at vn300.yaml's 100 Hz output rate
  EXPECT_EQ(rows, smoothed_rows);
  EXPECT_EQ(rows, smoothed.poses);
  // The FusionEngine output decodes: one Pose per smoothed pose.
  const testing::DecodedLog fe = testing::decode_file(*find_frontend("fe"), dir_ / "smoothed.p1log");
  EXPECT_EQ(fe.kinds.at("device_solution"), smoothed.poses);
  EXPECT_EQ(fe.counters.bad_frames, 0u);
}

TEST_F(SmoothScenario, BenchAgainstSmoothedReference) {
  bench::BenchOptions o;
  o.inputs = {(dir_ / "vn.bin").string()};
  o.config_path = std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/vn300.yaml";
  o.report_dir = (dir_ / "report").string();
  o.reference = "smoothed";
  o.html = false;
  bench::run_bench(o);
  std::ifstream in(dir_ / "report" / "metrics.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  ASSERT_TRUE(m.contains("navfuse_vs_smoothed"));
  ASSERT_TRUE(m.contains("device_vs_smoothed"));  // the simulated VN-300's own INS solution
  const double nf = m["navfuse_vs_smoothed"]["horizontal_m"]["rms"].get<double>();
  const double dev = m["device_vs_smoothed"]["horizontal_m"]["rms"].get<double>();
  std::printf("against the smoothed reference: navfuse forward %.3f m, device %.3f m horizontal RMS\n", nf, dev);
  // The forward filter is what was smoothed: it sits close to the smoothed track, and closer than
  // the simulated device (its error model is independent of navfuse's).
  EXPECT_GT(nf, 0.0);
  EXPECT_LT(nf, 2.0);
  EXPECT_LT(nf, dev);
  o.reference = "truth?";
  EXPECT_ANY_THROW(bench::run_bench(o));
}

}  // namespace
}  // namespace navfuse::apps

// Ctrl-C / SIGTERM during a replay (issue 15.3): the signal only sets a flag; the replay stops
// reading, commits complete outputs for what it processed and reports the signal.
#include <signal.h>

#include <atomic>
#include <string>

#include <gtest/gtest.h>

#include "apps/common/interrupt_signals.hpp"
#include "apps/replay/replay.hpp"
#include "frontends/common/stream_decoder.hpp"
#include "apps/common/frontend_registry.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

const std::string kDemo = std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/";

TEST(InterruptSignals, SignalIsCaughtAndRecorded) {
  const InterruptSignals signals;
  EXPECT_EQ(InterruptSignals::received().load(), 0);
  ASSERT_EQ(raise(SIGTERM), 0);  // would end the process without the handler
  EXPECT_EQ(InterruptSignals::received().load(), SIGTERM);
}

TEST(ReplayInterrupt, StopsEarlyWithCompleteOutputsAndSaysWhy) {
  const auto dir = testing::scratch_dir();
  ReplayOptions o;
  o.inputs = {kDemo + "vn300.vnb"};
  o.output_rate_hz = 0.0;
  o.fe_out = (dir / "out.p1log").string();
  const std::atomic<int> raised{SIGINT};  // as if Ctrl-C came at once
  o.interrupt = &raised;
  const ReplayResult r = run_replay(o);
  EXPECT_EQ(r.summary.interrupted_by, SIGINT);
  // The loop looks at the flag every 256 measurements: it stopped within the first ones.
  EXPECT_GT(r.imu_samples, 0u);
  EXPECT_LT(r.imu_samples, 256u);
  EXPECT_EQ(r.summary.to_json(false)["run"]["interrupted_by_signal"], SIGINT);

  // The output is committed and every frame in it is whole.
  const auto bytes = testing::read_bytes(dir / "out.p1log");
  ASSERT_FALSE(bytes.empty());
  const auto* fe = find_frontend("fe");
  ASSERT_NE(fe, nullptr);
  auto decoder = fe->make_decoder();
  struct Count final : frontends::DecodeSink {
    void on_measurement(const Measurement&) override {}
  } sink;
  decoder->feed(bytes, sink);
  decoder->finish(sink);
  EXPECT_GT(decoder->counters().frames, 0u);
  EXPECT_EQ(decoder->counters().bad_frames, 0u);
  EXPECT_EQ(decoder->counters().skipped_bytes, 0u);
}

}  // namespace
}  // namespace navfuse::apps

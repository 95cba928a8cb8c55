// Ctrl-C / SIGTERM during a replay (issue 15.3): the signal only sets a flag; the replay stops
// reading, commits complete outputs for what it processed and reports the signal.
#include <signal.h>

#include <atomic>
#include <cstdlib>
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

namespace navfuse::apps {
namespace {

// Issue 15.6: a pipe is read once; the bytes format detection took must still be replayed.
TEST(ReplayFromAPipe, LosesNoBytesToFormatDetection) {
  const auto dir = testing::scratch_dir();
  const std::string navfuse = std::string(NAVFUSE_BINARY_DIR) + "/apps/navfuse";
  const std::string log = kDemo + "vn300.vnb";  // 1.7 MB: far more than the 64 KiB probe
  const std::string from_pipe = (dir / "pipe.p1log").string();
  const std::string from_file = (dir / "file.p1log").string();
  ASSERT_EQ(std::system(("cat '" + log + "' | '" + navfuse + "' replay vn:/dev/stdin --rate 0 --quiet --fe-out '" +
                         from_pipe + "'").c_str()),
            0);
  ASSERT_EQ(std::system(("'" + navfuse + "' replay '" + log + "' --rate 0 --quiet --fe-out '" + from_file + "'").c_str()),
            0);
  const auto a = testing::read_bytes(from_pipe);
  EXPECT_GT(a.size(), 1'000'000u);
  EXPECT_EQ(a, testing::read_bytes(from_file));
}

}  // namespace
}  // namespace navfuse::apps

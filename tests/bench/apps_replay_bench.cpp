// End-to-end replay throughput (issue #8 goal: >= 620,000 IMU samples/s): a 200 Hz VN-300 log of
// the drive_short scenario (IMU, GNSS, INS at 50 Hz) plus its FusionEngine wheel-speed log,
// merged, filtered, and written as a FusionEngine Pose + PoseAux (+ IMUOutput) after every IMU
// sample (output rate 0), exactly what `navfuse replay --rate 0 --fe-out F` does. The logs are
// simulated once, outside the timed loop; items/s is IMU samples per second. Run with
// --benchmark_repetitions=5 for the median. Items/s use wall time, as the replay summary does:
// replay encodes and writes its outputs on a second thread, so the main thread's CPU time
// would leave that work out. On a shared machine, compare medians of idle runs.
#include <filesystem>

#include <benchmark/benchmark.h>

#include "apps/replay/replay.hpp"
#include "apps/simcmd/sim_command.hpp"

namespace navfuse::apps {
namespace {

const std::filesystem::path& logs_dir() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / "navfuse_apps_replay_bench";
    std::filesystem::create_directories(d);
    SimOptions o;
    o.scenario = "drive_short";
    o.format = "vn";
    o.out_path = (d / "vn.bin").string();
    o.wheel_out_path = (d / "wheel.p1log").string();
    o.device_rate_hz = 50.0;
    run_sim(o);
    return d;
  }();
  return dir;
}

void BM_ReplayVn300WithWheelPosePerImuSample(benchmark::State& state) {
  const auto& dir = logs_dir();
  ReplayOptions o;
  o.inputs = {"vn:" + (dir / "vn.bin").string(), "fe:" + (dir / "wheel.p1log").string()};
  o.output_rate_hz = 0.0;
  o.fe_out = (dir / "out.p1log").string();
  std::uint64_t samples = 0;
  double summary_rate_sum = 0.0;
  for (auto _ : state) {
    const ReplayResult r = run_replay(o);
    samples += r.imu_samples;
    summary_rate_sum += r.summary.run->imu_samples_per_s;
    benchmark::DoNotOptimize(r.poses);
  }
  // items_per_second covers the whole call (configuration, opening and committing files);
  // summary_imu_per_s is what the replay summary prints: the fusion loop, including writing.
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["summary_imu_per_s"] = summary_rate_sum / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ReplayVn300WithWheelPosePerImuSample)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace navfuse::apps

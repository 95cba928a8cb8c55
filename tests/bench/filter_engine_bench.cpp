// Full filter loop throughput: 200 Hz IMU + 10 Hz GNSS position/velocity + 10 Hz vehicle speed
// (the simulator's short drive: static start, alignment, turns, stops), in IMU samples per
// second. Goal (issue #7): >= 1,000,000 IMU samples/s on one core (median).
#include <benchmark/benchmark.h>

#include "filter/engine.hpp"
#include "tests/filter/drive_stream.hpp"

namespace {

const navfuse::filter::test::DriveStream& stream() {
  static const navfuse::filter::test::DriveStream s = navfuse::filter::test::make_drive_stream(190.0);
  return s;
}

// process() only: what a replay that outputs at a low rate pays.
void BM_FilterLoop(benchmark::State& state) {
  const auto& s = stream();
  for (auto _ : state) {
    state.PauseTiming();
    navfuse::filter::Engine engine(s.options);
    state.ResumeTiming();
    for (const auto& m : s.measurements) engine.process(m);
    benchmark::DoNotOptimize(engine.imu_epoch());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * s.imu_samples));
}
BENCHMARK(BM_FilterLoop)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

// process() plus a full NavSolution at every IMU sample (pose output at the IMU rate).
void BM_FilterLoopWithSolution(benchmark::State& state) {
  const auto& s = stream();
  for (auto _ : state) {
    state.PauseTiming();
    navfuse::filter::Engine engine(s.options);
    state.ResumeTiming();
    for (const auto& m : s.measurements) {
      engine.process(m);
      if (m.index() == 0) benchmark::DoNotOptimize(engine.solution().lat_rad);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * s.imu_samples));
}
BENCHMARK(BM_FilterLoopWithSolution)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

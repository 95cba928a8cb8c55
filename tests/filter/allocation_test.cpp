// "No heap allocation per IMU sample" (DESIGN.md quality bar), proved with a counting allocator:
// this binary replaces the global operator new, runs the filter on a 200 Hz IMU + 10 Hz GNSS +
// 10 Hz speed stream past alignment, then counts allocations over the rest of the stream.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "filter/engine.hpp"
#include "tests/filter/drive_stream.hpp"

namespace {
std::atomic<std::size_t> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace navfuse::filter {
namespace {

TEST(FilterAllocation, NoHeapAllocationPerImuSampleAfterWarmUp) {
  // 30 s static start, alignment at ~33 s, then 27 s of driving with turns.
  const test::DriveStream stream = test::make_drive_stream(60.0);
  Engine engine(stream.options);
  const std::size_t warm_up = stream.measurements.size() / 2;  // ~30 s: levelled, ZUPTs running
  // Warm up until full navigation (the first solution fill loads the geoid grid once).
  std::size_t i = 0;
  for (; i < stream.measurements.size(); ++i) {
    engine.process(stream.measurements[i]);
    (void)engine.solution();
    if (i >= warm_up && engine.solution().mode == NavMode::kNavigation) break;
  }
  ASSERT_EQ(engine.solution().mode, NavMode::kNavigation);
  const std::uint64_t epoch_before = engine.imu_epoch();
  const std::size_t before = g_allocations.load();
  for (++i; i < stream.measurements.size(); ++i) {
    engine.process(stream.measurements[i]);
    (void)engine.solution();
  }
  const std::size_t allocations = g_allocations.load() - before;
  const std::uint64_t samples = engine.imu_epoch() - epoch_before;
  EXPECT_GT(samples, 4000u);
  EXPECT_EQ(allocations, 0u) << "over " << samples << " IMU samples";
  EXPECT_GT(engine.stats().of(MeasurementKind::kGnssPosition).used, 250u);
  EXPECT_GT(engine.stats().of(MeasurementKind::kVehicleSpeed).used, 200u);
}

}  // namespace
}  // namespace navfuse::filter

// Spilled storage and external sorting (apps/common/spill_file.hpp, external_sort.hpp) and the
// error statistics built on them (apps/replay/error_stats.hpp), checked against the direct
// computation: every value in a std::vector, std::sort, nearest ranks picked by index. Small run
// and buffer sizes force many runs through the temporary file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "apps/common/external_sort.hpp"
#include "apps/common/spill_file.hpp"
#include "apps/replay/error_stats.hpp"

namespace navfuse::apps {
namespace {

TEST(SpillFile, ReadsBackEveryRecordInOrderWhileTheLastStaysAmendable) {
  SpillFile<std::int64_t> file(7);  // flushes every 6 records
  for (std::int64_t i = 0; i < 100; ++i) file.push_back(i * i);
  file.back() = -1;  // the last record is still in memory and can be amended
  ASSERT_EQ(file.size(), 100u);
  auto r = file.reader(0, 5);
  std::int64_t v = 0;
  for (std::int64_t i = 0; i < 99; ++i) {
    ASSERT_TRUE(r.next(v));
    EXPECT_EQ(v, i * i);
  }
  ASSERT_TRUE(r.next(v));
  EXPECT_EQ(v, -1);
  EXPECT_FALSE(r.next(v));
  // A reader from the middle, and one that keeps up while appending goes on.
  auto mid = file.reader(50);
  ASSERT_TRUE(mid.next(v));
  EXPECT_EQ(v, 2500);
  auto live = file.reader(99);
  ASSERT_TRUE(live.next(v));
  file.push_back(7);
  ASSERT_TRUE(live.next(v));
  EXPECT_EQ(v, 7);
}

TEST(ExternalSort, GivesExactlyTheSortedSequence) {
  std::mt19937_64 rng(15);
  std::lognormal_distribution<double> error(0.0, 1.5);
  for (const std::size_t n : {0u, 1u, 9u, 10u, 11u, 1000u, 25'013u}) {
    ExternalSort<double> sorter(10);  // runs of 10 values
    std::vector<double> all;
    for (std::size_t i = 0; i < n; ++i) {
      // Ties too: every fifth value repeats one before it.
      const double v = (i % 5 == 4) ? all[i / 2] : error(rng);
      sorter.add(v);
      all.push_back(v);
    }
    std::sort(all.begin(), all.end());
    ASSERT_EQ(sorter.size(), n);
    std::vector<double> merged;
    auto r = sorter.sorted(3);
    for (double v; r.next(v);) merged.push_back(v);
    EXPECT_EQ(merged, all) << n << " values";
  }
}

TEST(ErrorStats, SpilledValuesGiveTheFiguresOfAnInMemorySort) {
  // 100,000 errors: 12 runs of the default 8192 values through the temporary file.
  std::mt19937_64 rng(10);
  std::gamma_distribution<double> error(2.0, 0.7);
  ErrorStats stats;
  std::vector<double> all;
  for (int i = 0; i < 100'000; ++i) {
    const double v = error(rng);
    stats.add(v);
    all.push_back(v);
  }
  std::sort(all.begin(), all.end());
  double sum_sq = 0.0;
  for (double v : all) sum_sq += v * v;  // ascending, as an in-memory summary sums
  const auto at_rank = [&](double p) {
    return all[static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(all.size()))) - 1];
  };
  const ErrorSummary s = stats.summary();
  EXPECT_EQ(s.samples, all.size());
  // Exact equality: the same values, summed in the same order.
  EXPECT_EQ(s.rms, std::sqrt(sum_sq / static_cast<double>(all.size())));
  EXPECT_EQ(s.p50, at_rank(50.0));
  EXPECT_EQ(s.p95, at_rank(95.0));
  EXPECT_EQ(s.p99, at_rank(99.0));
  EXPECT_EQ(s.max, all.back());
  EXPECT_EQ(nearest_rank(100'000, 95.0), 95'000u);
  EXPECT_EQ(nearest_rank(3, 50.0), 2u);
}

}  // namespace
}  // namespace navfuse::apps

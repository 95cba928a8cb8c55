// The median interval between consecutive times of a series (a solution's sample times, the GNSS
// fix times), taken without holding the series in memory: the intervals are sorted externally
// (apps/common/external_sort.hpp). The median is the interval at index n / 2 of the n sorted
// intervals (the upper median for even n), the element std::nth_element would place there.
#pragma once

#include <cstdint>
#include <optional>

#include "apps/common/external_sort.hpp"

namespace navfuse::apps::bench {

class IntervalMedian {
 public:
  // Times in non-decreasing order.
  void add(std::int64_t time_ns) {
    if (last_ns_) intervals_.add(time_ns - *last_ns_);
    last_ns_ = time_ns;
  }
  // 0 with fewer than two times.
  std::int64_t median_ns() const {
    const std::size_t mid = intervals_.size() / 2;
    auto sorted = intervals_.sorted();
    std::size_t i = 0;
    for (std::int64_t dt; sorted.next(dt); ++i) {
      if (i == mid) return dt;
    }
    return 0;
  }

 private:
  std::optional<std::int64_t> last_ns_;
  ExternalSort<std::int64_t> intervals_;
};

}  // namespace navfuse::apps::bench

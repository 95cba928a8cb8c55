// The median of a sample, for the calibration's robust scale estimates.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace navfuse::calib {

// The upper median (element n/2 in order) of a non-empty `v`; reorders `v`.
inline double median_in_place(std::vector<double>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace navfuse::calib

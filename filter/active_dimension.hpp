// The fixed sizes the EKF is compiled for: every value StateSelection::active_dimension() can
// return, listed once. The covariance step and the measurement update instantiate their
// fixed-size kernels for each of them through with_active_dimension (fixed sizes let Eigen unroll
// and vectorise the small products instead of running its dynamic-size kernels).
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "filter/state_layout.hpp"

namespace navfuse::filter {

inline constexpr std::array<int, 7> kActiveDimensions{sx::kCoreCount,     sx::kWheelScale + 1, sx::kMountYaw + 1,
                                                     sx::kLeverArm + 3,  sx::kGyroScale + 3,  sx::kAccelScale + 3,
                                                     sx::kCount};
static_assert(kActiveDimensions.back() == sx::kCount, "the largest block holds every state");

namespace detail {
template <class F, std::size_t... I>
void with_active_dimension(int n, F&& f, std::index_sequence<I...>) {
  // The listed dimension that equals n; the full set when none does.
  (void)((n == kActiveDimensions[I] && (f(std::integral_constant<int, kActiveDimensions[I]>{}), true)) ||
         ... || (f(std::integral_constant<int, sx::kCount>{}), true));
}
}  // namespace detail

// Calls f(std::integral_constant<int, N>{}) with N == n, one of kActiveDimensions (kCount for
// any other n, which StateSelection never produces).
template <class F>
void with_active_dimension(int n, F&& f) {
  detail::with_active_dimension(n, std::forward<F>(f), std::make_index_sequence<kActiveDimensions.size()>{});
}

}  // namespace navfuse::filter

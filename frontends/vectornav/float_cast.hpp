// double -> IEEE binary32 for wire fields. Converting a double beyond the float range is
// undefined behaviour in C++, so such values saturate at +-FLT_MAX; NaN stays NaN.
#pragma once

#include <algorithm>
#include <limits>

namespace navfuse::frontends::vectornav {

inline float to_f32(double v) {
  constexpr double kMax = std::numeric_limits<float>::max();
  return static_cast<float>(std::clamp(v, -kMax, kMax));
}

}  // namespace navfuse::frontends::vectornav

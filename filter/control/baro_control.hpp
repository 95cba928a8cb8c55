// When and how barometric pressure is fused (the model is measurements/baro_height.hpp). Only
// with `baro.height_std_m` configured. Pressure height is relative (weather shifts it by metres),
// so the first sample after the filter knows its position anchors it: offset = filter height -
// pressure altitude, with the filter's own height std added to the measurement std from then on
// (the anchor is no better than the height it was taken from). A restart re-anchors.
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::filter {

FuseResult fuse(FilterCore& core, const FilterOptions& o, const Pressure& m, double shift_s);

}  // namespace navfuse::filter

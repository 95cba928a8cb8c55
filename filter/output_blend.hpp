// Jump-free position output: the filter's corrections are applied at once, but a large one (an
// RTK float-to-fixed transition, a re-anchoring to GNSS) reaches the reported position over a
// time constant instead of in one step, so a vehicle controller or a map built from the output
// never sees the position jump.
//
// The reported position is the filter's plus an offset (NED metres). A correction that moves the
// filter's position by d with |d| >= `output.jump_blend_min_m` subtracts d from the offset, so the
// output does not move at that epoch; the offset then decays as exp(-t / output.jump_blend_s).
// The filter state, its covariance and everything fused are untouched; the reported position
// std grows by the offset still pending. This is the output predictor of PX4's EKF2 reduced to
// its position part (a complementary filter between the filter's state and the output), and the
// "position jump smoothing" commercial RTK/INS receivers offer; corrections below the threshold
// (every ordinary RTK update: millimetres to centimetres) pass straight through.
#pragma once

#include <cstdint>

#include <Eigen/Core>

namespace navfuse::filter {

struct FilterCore;
struct FilterOptions;
struct NavState;

struct OutputBlend {
  Eigen::Vector3d offset_ned_m = Eigen::Vector3d::Zero();  // output minus filter position
  std::uint64_t jumps_blended = 0;
};

// After a correction of the position from `before` to core.x: blends it when it is large enough.
void blend_position_jump(FilterCore& core, const FilterOptions& o, const NavState& before);

// The offset's decay over one IMU step of `dt_s`.
void decay_output_blend(FilterCore& core, const FilterOptions& o, double dt_s);

// The reported state and position variance (NED): the filter's, moved by the pending offset.
void apply_output_blend(const OutputBlend& blend, NavState& x, Eigen::Matrix3d& pos_cov_ned_m2);

}  // namespace navfuse::filter

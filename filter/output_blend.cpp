#include "filter/output_blend.hpp"

#include <cmath>

#include "filter/filter_core.hpp"
#include "filter/nav_state.hpp"

namespace navfuse::filter {
namespace {

// Below this the offset is gone (a tenth of a millimetre).
constexpr double kNegligible_m = 1e-4;

}  // namespace

void blend_position_jump(FilterCore& c, const FilterOptions& o, const NavState& before) {
  if (!(o.output_jump_blend_s > 0.0)) return;
  // state_difference(before, after) is before - after in NED metres (nav_state.hpp).
  const Eigen::Vector3d moved_ned_m = -state_difference(before, c.x).segment<3>(sx::kPos);
  if (moved_ned_m.norm() < o.output_jump_blend_min_m) return;
  c.output_blend.offset_ned_m -= moved_ned_m;
  ++c.output_blend.jumps_blended;
}

void decay_output_blend(FilterCore& c, const FilterOptions& o, double dt_s) {
  Eigen::Vector3d& offset = c.output_blend.offset_ned_m;
  if (offset.isZero(0.0)) return;
  if (!(o.output_jump_blend_s > 0.0) || offset.norm() < kNegligible_m) {
    offset.setZero();
    return;
  }
  offset *= std::exp(-dt_s / o.output_jump_blend_s);
}

void apply_output_blend(const OutputBlend& blend, NavState& x, Eigen::Matrix3d& pos_cov_ned_m2) {
  if (blend.offset_ned_m.isZero(0.0)) return;
  // inject_error(x, dx) moves x by -dx (nav_state.hpp).
  StateVector dx = StateVector::Zero();
  dx.segment<3>(sx::kPos) = -blend.offset_ned_m;
  inject_error(x, dx);
  // The reported position is off the filter's best estimate by the offset: its std says so.
  pos_cov_ned_m2.diagonal() += blend.offset_ned_m.cwiseAbs2();
}

}  // namespace navfuse::filter

#include "frontends/mip/filter_status.hpp"

#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {

FilterStatusWord status_from_solution(const NavSolution& s) {
  FilterStatusWord w;
  w.dynamics_mode = filter::kDynamicsDefault;  // the only CV7 value (L4385)
  switch (s.mode) {
    case NavMode::kInvalid: w.filter_state = 0; break;  // no CV7 value; 0 is what GX5 called STARTUP
    case NavMode::kInitializing: w.filter_state = filter::kStateInit; break;
    case NavMode::kVerticalGyro: w.filter_state = filter::kStateVerticalGyro; break;
    case NavMode::kAhrs: w.filter_state = filter::kStateAhrs; break;
    case NavMode::kNavigation:
    case NavMode::kDeadReckoning:
    case NavMode::kSmoothed: w.filter_state = filter::kStateFullNav; break;  // MIP has no post-processed state
  }
  std::uint16_t condition = filter::kConditionStable;
  if (s.mode == NavMode::kInvalid || s.mode == NavMode::kInitializing) condition = filter::kConditionConverging;
  if (s.status_flags & NavSolution::kStatusDiverged) condition = filter::kConditionUnstable;
  w.status_flags = condition;
  if (s.mode == NavMode::kDeadReckoning)
    w.status_flags |= filter::kFlagPositionWarning | filter::kFlagVelocityWarning;
  return w;
}

bool apply_status(const FilterStatusWord& w, NavSolution& s) {
  switch (w.filter_state) {
    case filter::kStateInit: s.mode = NavMode::kInitializing; break;
    case filter::kStateVerticalGyro: s.mode = NavMode::kVerticalGyro; break;
    case filter::kStateAhrs: s.mode = NavMode::kAhrs; break;
    case filter::kStateFullNav: {
      const std::uint16_t dr = filter::kFlagPositionWarning | filter::kFlagVelocityWarning;
      s.mode = (w.status_flags & dr) == dr ? NavMode::kDeadReckoning : NavMode::kNavigation;
      if (s.mode == NavMode::kDeadReckoning) s.status_flags |= NavSolution::kStatusGnssOutage;
      break;
    }
    default: s.mode = NavMode::kInvalid; break;
  }
  s.device_status = (static_cast<std::uint32_t>(w.filter_state) << 16) | w.status_flags;
  const bool solution_error = (w.status_flags & filter::kFlagSolutionError) != 0;
  if ((w.status_flags & filter::kConditionMask) == filter::kConditionUnstable || solution_error)
    s.status_flags |= NavSolution::kStatusDiverged;
  return !solution_error;
}

}  // namespace navfuse::frontends::mip

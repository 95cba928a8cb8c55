#include "filter/mode_machine.hpp"

namespace navfuse::filter {

void update_mode(FilterCore& c, const FilterOptions& o) {
  ModeState& m = c.mode;
  NavMode mode = NavMode::kInitializing;
  if (m.levelled) mode = NavMode::kVerticalGyro;
  if (m.levelled && m.heading_known) mode = NavMode::kAhrs;
  if (!c.navigating()) {
    m.navigating_since_ns = INT64_MIN;
  } else if (m.navigating_since_ns == INT64_MIN) {
    m.navigating_since_ns = c.x.time_ns;
  }
  if (c.navigating()) {
    const double since_fix_s = seconds_since(c.x.time_ns, m.last_absolute_position_ns);
    mode = since_fix_s <= o.gnss_timeout_s ? NavMode::kNavigation : NavMode::kDeadReckoning;
  }
  if (mode == NavMode::kNavigation) m.diverged = false;
  m.mode = mode;
  m.reached_mask |= 1u << static_cast<unsigned>(mode);
}

}  // namespace navfuse::filter

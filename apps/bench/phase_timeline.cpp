#include "apps/bench/phase_timeline.hpp"

#include <algorithm>
#include <cmath>

namespace navfuse::apps::bench {

void PhaseTimeline::add(std::int64_t time_ns, PhaseLabel label) {
  if (!times_.empty() && time_ns <= times_.back()) return;
  times_.push_back(time_ns);
  labels_.push_back(label);
}

std::optional<PhaseLabel> PhaseTimeline::at(std::int64_t time_ns) const {
  if (times_.empty()) return std::nullopt;
  const auto after = std::upper_bound(times_.begin(), times_.end(), time_ns);
  const std::size_t i = after == times_.begin() ? 0 : static_cast<std::size_t>(after - times_.begin()) - 1;
  return labels_[i];
}

std::vector<TimeInterval> PhaseTimeline::runs(bool PhaseLabel::*flag) const {
  std::vector<TimeInterval> out;
  bool open = false;
  for (std::size_t i = 0; i < times_.size(); ++i) {
    const bool on = labels_[i].*flag;
    if (on && !open) {
      out.push_back({times_[i], times_[i]});
      open = true;
    } else if (!on && open) {
      out.back().end_ns = times_[i];
      open = false;
    }
  }
  if (open) out.back().end_ns = times_.back();
  return out;
}

std::int64_t max_fix_age_ns(const std::vector<std::int64_t>& fix_times_ns) {
  constexpr std::int64_t kMinAgeNs = 1'000'000'000;
  if (fix_times_ns.size() < 2) return kMinAgeNs;
  std::vector<std::int64_t> dt;
  dt.reserve(fix_times_ns.size() - 1);
  for (std::size_t i = 1; i < fix_times_ns.size(); ++i) dt.push_back(fix_times_ns[i] - fix_times_ns[i - 1]);
  const auto mid = dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2);
  std::nth_element(dt.begin(), mid, dt.end());
  return std::max(kMinAgeNs, static_cast<std::int64_t>(std::llround(2.5 * static_cast<double>(*mid))));
}

bool in_gnss_outage(const std::vector<std::int64_t>& fix_times_ns, std::int64_t time_ns, std::int64_t max_age_ns) {
  // Last fix at or before the time.
  const auto after = std::upper_bound(fix_times_ns.begin(), fix_times_ns.end(), time_ns);
  if (after == fix_times_ns.begin()) return true;
  return time_ns - *(after - 1) > max_age_ns;
}

}  // namespace navfuse::apps::bench

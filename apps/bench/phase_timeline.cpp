#include "apps/bench/phase_timeline.hpp"

#include <algorithm>
#include <cmath>

#include "apps/bench/interval_median.hpp"

namespace navfuse::apps::bench {

void PhaseTimeline::add(std::int64_t time_ns, PhaseLabel label) {
  if (!points_.empty() && time_ns <= last_ns_) return;
  points_.push_back({.time_ns = time_ns, .label = label});
  last_ns_ = time_ns;
  outages_.add(time_ns, label.gnss_outage);
  stationary_.add(time_ns, label.stationary);
}

void PhaseTimeline::Runs::add(std::int64_t time_ns, bool on) {
  if (on && !open_since_ns) {
    open_since_ns = time_ns;
  } else if (!on && open_since_ns) {
    closed.push_back({*open_since_ns, time_ns});
    open_since_ns.reset();
  }
}

std::vector<TimeInterval> PhaseTimeline::Runs::intervals(std::int64_t last_ns) const {
  std::vector<TimeInterval> out = closed;
  if (open_since_ns) out.push_back({*open_since_ns, last_ns});
  return out;
}

std::optional<PhaseLabel> PhaseTimeline::Cursor::at(std::int64_t time_ns) {
  if (last_asked_ns_ && time_ns < *last_asked_ns_) points_ = Points(timeline_->points_.reader(), &time_of);
  last_asked_ns_ = time_ns;
  points_.advance(time_ns, /*inclusive=*/true);
  // The last point at or before the time; before the first point, the first point's.
  if (points_.last()) return points_.last()->label;
  if (points_.next()) return points_.next()->label;
  return std::nullopt;
}

namespace {

std::int64_t max_fix_age(const ExternalSort<std::int64_t>& fix_times_ns) {
  constexpr std::int64_t kMinAgeNs = 1'000'000'000;
  if (fix_times_ns.size() < 2) return kMinAgeNs;
  IntervalMedian median;
  auto sorted = fix_times_ns.sorted();
  for (std::int64_t t; sorted.next(t);) median.add(t);
  return std::max(kMinAgeNs, static_cast<std::int64_t>(std::llround(2.5 * static_cast<double>(median.median_ns()))));
}

}  // namespace

GnssOutageDetector::GnssOutageDetector(const ExternalSort<std::int64_t>& fix_times_ns)
    : fix_times_ns_(&fix_times_ns), max_age_ns_(max_fix_age(fix_times_ns)), fixes_(fix_times_ns.sorted(), &time_of) {}

bool GnssOutageDetector::at(std::int64_t time_ns) {
  if (last_asked_ns_ && time_ns < *last_asked_ns_) fixes_ = Fixes(fix_times_ns_->sorted(), &time_of);
  last_asked_ns_ = time_ns;
  fixes_.advance(time_ns, /*inclusive=*/true);
  if (!fixes_.last()) return true;
  return time_ns - *fixes_.last() > max_age_ns_;
}

}  // namespace navfuse::apps::bench

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
  if (started_ && time_ns < last_asked_ns_) *this = timeline_->cursor();
  if (!started_) {
    started_ = true;
    if (PhasePointRecord p; reader_.next(p)) current_ = p;
    if (PhasePointRecord p; reader_.next(p)) next_ = p;
  }
  last_asked_ns_ = time_ns;
  if (!current_) return std::nullopt;
  // The last point at or before the time (the first point before it).
  while (next_ && next_->time_ns <= time_ns) {
    current_ = next_;
    if (PhasePointRecord p; reader_.next(p)) {
      next_ = p;
    } else {
      next_.reset();
    }
  }
  return current_->label;
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
    : fixes_(&fix_times_ns), max_age_ns_(max_fix_age(fix_times_ns)), reader_(fix_times_ns.sorted()) {}

bool GnssOutageDetector::at(std::int64_t time_ns) {
  if (started_ && time_ns < last_asked_ns_) {
    reader_ = fixes_->sorted();
    last_fix_ns_.reset();
    next_fix_ns_.reset();
    started_ = false;
  }
  if (!started_) {
    started_ = true;
    if (std::int64_t t; reader_.next(t)) next_fix_ns_ = t;
  }
  last_asked_ns_ = time_ns;
  // Last fix at or before the time.
  while (next_fix_ns_ && *next_fix_ns_ <= time_ns) {
    last_fix_ns_ = next_fix_ns_;
    if (std::int64_t t; reader_.next(t)) {
      next_fix_ns_ = t;
    } else {
      next_fix_ns_.reset();
    }
  }
  if (!last_fix_ns_) return true;
  return time_ns - *last_fix_ns_ > max_age_ns_;
}

}  // namespace navfuse::apps::bench

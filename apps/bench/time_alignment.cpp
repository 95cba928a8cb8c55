#include "apps/bench/time_alignment.hpp"

#include <cmath>

#include "apps/bench/interval_median.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps::bench {
namespace {

double shorter_arc_rad(double from_rad, double to_rad) { return std::remainder(to_rad - from_rad, 2.0 * rot::kPi); }

}  // namespace

std::int64_t median_interval_ns(const TrackView& samples) {
  IntervalMedian median;
  TrackView::Reader r = samples.reader();
  for (TrackSample s; r.next(s);) median.add(s.time_ns);
  return median.median_ns();
}

std::int64_t default_max_gap_ns(const TrackView& samples) {
  return static_cast<std::int64_t>(std::llround(kDefaultGapIntervals * static_cast<double>(median_interval_ns(samples))));
}

TrackSample interpolate(const TrackSample& a, const TrackSample& b, double f) {
  TrackSample s = a;
  s.time_ns = a.time_ns + static_cast<std::int64_t>(std::llround(f * static_cast<double>(b.time_ns - a.time_ns)));
  s.valid = a.valid & b.valid;
  s.lat_rad += f * (b.lat_rad - a.lat_rad);
  s.lon_rad = rot::wrap_pi(a.lon_rad + f * shorter_arc_rad(a.lon_rad, b.lon_rad));
  s.height_m += f * (b.height_m - a.height_m);
  s.vel_ned_mps += f * (b.vel_ned_mps - a.vel_ned_mps);
  for (int i = 0; i < 3; ++i) s.rpy_rad[i] = rot::wrap_pi(a.rpy_rad[i] + f * shorter_arc_rad(a.rpy_rad[i], b.rpy_rad[i]));
  s.pos_std_ned_m += f * (b.pos_std_ned_m - a.pos_std_ned_m);
  s.vel_std_ned_mps += f * (b.vel_std_ned_mps - a.vel_std_ned_mps);
  s.att_std_rpy_rad += f * (b.att_std_rpy_rad - a.att_std_rpy_rad);
  return s;
}

TrackInterpolator::TrackInterpolator(const TrackView& samples, std::int64_t max_gap_ns)
    : samples_(samples), max_gap_ns_(max_gap_ns), cursor_(samples_.reader(), &time_of) {}

std::optional<TrackSample> TrackInterpolator::at(std::int64_t time_ns, Miss* miss) {
  const auto report = [&](Miss m) {
    if (miss != nullptr) *miss = m;
  };
  if (last_asked_ns_ && time_ns < *last_asked_ns_) cursor_ = Cursor(samples_.reader(), &time_of);
  last_asked_ns_ = time_ns;
  cursor_.advance(time_ns, /*inclusive=*/false);
  const std::optional<TrackSample>& before = cursor_.last();
  const std::optional<TrackSample>& after = cursor_.next();
  if (!after) {
    report(Miss::kOutside);
    return std::nullopt;
  }
  if (after->time_ns == time_ns) {
    report(Miss::kNone);
    return *after;
  }
  if (!before) {
    report(Miss::kOutside);
    return std::nullopt;
  }
  const TrackSample& a = *before;
  const TrackSample& b = *after;
  if (b.time_ns - a.time_ns > max_gap_ns_) {
    report(Miss::kGap);
    return std::nullopt;
  }
  report(Miss::kNone);
  const double f = static_cast<double>(time_ns - a.time_ns) / static_cast<double>(b.time_ns - a.time_ns);
  TrackSample s = interpolate(a, b, f);
  s.time_ns = time_ns;
  return s;
}

}  // namespace navfuse::apps::bench

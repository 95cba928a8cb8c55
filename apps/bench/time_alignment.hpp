// Time alignment of two solutions for `navfuse bench`: one solution is sampled at the other's
// times by interpolating between its two neighbouring samples.
//
// Interpolation never invents data: a time before the first or after the last sample is
// "outside", and a time between two neighbours further apart than the gap limit is in a "gap"
// (a device that stopped reporting, a solution that lost validity, a filter restart). Both are
// skipped and counted rather than bridged, because a straight line across a dropout hides exactly
// the behaviour a benchmark is meant to show.
//
// Between neighbours: position (latitude, longitude, height), velocity and the uncertainties
// are linear in time; each Euler angle is linear along the shorter arc (a heading going from
// 179 deg to -179 deg passes through 180, not through 0), as apps/replay/truth_track.hpp does for
// truth. The mode, validity and status of the earlier neighbour apply (they are step functions).
// At the output rates compared (10-200 Hz) the linearisation error is well under a millimetre.
//
// The interpolator streams: it reads its track forward and keeps only the two neighbours of the
// last time asked, so lookups at increasing times (the sampled solution's times) cost one pass
// over the track in all. A time before the previous one restarts the pass (correct, but slow).
#pragma once

#include <cstdint>
#include <optional>

#include "apps/bench/forward_cursor.hpp"
#include "apps/bench/solution_track.hpp"

namespace navfuse::apps::bench {

// Gap limit used unless the user gives one: this many median sample intervals. 3 tolerates one or
// two lost messages of a steady stream yet rejects a real dropout.
inline constexpr double kDefaultGapIntervals = 3.0;

// Median interval between consecutive samples (0 with fewer than two samples).
std::int64_t median_interval_ns(const TrackView& samples);
// kDefaultGapIntervals median intervals (0 with fewer than two samples: nothing to bridge).
std::int64_t default_max_gap_ns(const TrackView& samples);

class TrackInterpolator {
 public:
  enum class Miss { kNone, kOutside, kGap };

  // The track behind `samples` must outlive the interpolator.
  TrackInterpolator(const TrackView& samples, std::int64_t max_gap_ns);

  // The track at `time_ns`: a sample itself when the time matches one, else interpolated between
  // its neighbours; nullopt when outside the track or in a gap (`miss` says which). Cheapest with
  // non-decreasing times (see the header comment).
  std::optional<TrackSample> at(std::int64_t time_ns, Miss* miss = nullptr);

  std::int64_t max_gap_ns() const { return max_gap_ns_; }
  bool empty() const { return samples_.empty(); }

 private:
  static std::int64_t time_of(const TrackSample& s) { return s.time_ns; }
  using Cursor = ForwardCursor<TrackView::Reader, TrackSample, decltype(&time_of)>;

  TrackView samples_;
  std::int64_t max_gap_ns_;
  // last(): the last sample before the last time asked; next(): the first at or after it.
  Cursor cursor_;
  std::optional<std::int64_t> last_asked_ns_;
};

// Linear interpolation between `a` and `b` at fraction f in [0, 1] (see the header comment).
TrackSample interpolate(const TrackSample& a, const TrackSample& b, double f);

}  // namespace navfuse::apps::bench

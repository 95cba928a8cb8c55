#include "apps/bench/solution_track.hpp"

namespace navfuse::apps::bench {

TrackSample track_sample_from(const NavSolution& s) {
  TrackSample t;
  t.time_ns = s.header.time_ns;
  t.mode = s.mode;
  t.valid = s.header.valid;
  t.status_flags = s.status_flags;
  t.lat_rad = s.lat_rad;
  t.lon_rad = s.lon_rad;
  t.height_m = s.height_m;
  t.vel_ned_mps = s.vel_ned_mps;
  t.rpy_rad = s.rpy_rad;
  t.pos_std_ned_m = s.pos_std_ned_m;
  t.vel_std_ned_mps = s.vel_std_ned_mps;
  t.att_std_rpy_rad = s.att_std_rpy_rad;
  return t;
}

std::string_view to_string(Quantity q) {
  switch (q) {
    case Quantity::kPosition: return "position";
    case Quantity::kVelocity: return "velocity";
    case Quantity::kAttitude: return "attitude";
    case Quantity::kHeading: return "heading";
    case Quantity::kCount: break;
  }
  return "unknown";
}

bool has(const TrackSample& s, Quantity q) {
  switch (q) {
    case Quantity::kPosition: return (s.valid & NavSolution::kValidPosition) != 0;
    case Quantity::kVelocity: return (s.valid & NavSolution::kValidVelocity) != 0;
    case Quantity::kAttitude: return (s.valid & NavSolution::kValidAttitude) != 0;
    case Quantity::kHeading:
      return (s.valid & NavSolution::kValidAttitude) != 0 && (s.valid & NavSolution::kValidHeading) != 0;
    case Quantity::kCount: break;
  }
  return false;
}

bool has_std(const TrackSample& s, Quantity q) {
  switch (q) {
    case Quantity::kPosition: return (s.valid & NavSolution::kValidPositionStd) != 0;
    case Quantity::kVelocity: return (s.valid & NavSolution::kValidVelocityStd) != 0;
    case Quantity::kAttitude:
    case Quantity::kHeading: return (s.valid & NavSolution::kValidAttitudeStd) != 0;
    case Quantity::kCount: break;
  }
  return false;
}

namespace {

// Copies into `into` the parts `from` carries, with their uncertainties.
void merge_parts(const TrackSample& from, TrackSample& into) {
  constexpr std::uint32_t kPosition = NavSolution::kValidPosition | NavSolution::kValidPositionStd;
  constexpr std::uint32_t kVelocity = NavSolution::kValidVelocity | NavSolution::kValidVelocityStd;
  constexpr std::uint32_t kAttitude =
      NavSolution::kValidAttitude | NavSolution::kValidAttitudeStd | NavSolution::kValidHeading;
  if (has(from, Quantity::kPosition)) {
    into.valid = (into.valid & ~kPosition) | (from.valid & kPosition);
    into.lat_rad = from.lat_rad;
    into.lon_rad = from.lon_rad;
    into.height_m = from.height_m;
    into.pos_std_ned_m = from.pos_std_ned_m;
  }
  if (has(from, Quantity::kVelocity)) {
    into.valid = (into.valid & ~kVelocity) | (from.valid & kVelocity);
    into.vel_ned_mps = from.vel_ned_mps;
    into.vel_std_ned_mps = from.vel_std_ned_mps;
  }
  if (has(from, Quantity::kAttitude)) {
    into.valid = (into.valid & ~kAttitude) | (from.valid & kAttitude);
    into.rpy_rad = from.rpy_rad;
    into.att_std_rpy_rad = from.att_std_rpy_rad;
  }
  // The later message of an epoch knows at least as much about the mode.
  into.mode = from.mode;
  into.status_flags |= from.status_flags;
}

}  // namespace

bool SolutionTrack::append(const TrackSample& s) {
  if (!samples_.empty() && s.time_ns <= samples_.back().time_ns) {
    if (s.time_ns == samples_.back().time_ns) {
      merge_parts(s, samples_.back());
      return true;
    }
    ++dropped_;
    return false;
  }
  samples_.push_back(s);
  return true;
}

TrackView SolutionTrack::with(Quantity q, bool navigating_only) const {
  return TrackView(*this, {.quantity = q, .navigating_only = navigating_only, .estimating_only = false});
}

TrackView SolutionTrack::with_any() const {
  return TrackView(*this, {.quantity = std::nullopt, .navigating_only = false, .estimating_only = false});
}

bool TrackFilter::matches(const TrackSample& s) const {
  if (navigating_only && !is_navigating(s.mode)) return false;
  if (estimating_only && s.mode <= NavMode::kInitializing) return false;
  if (quantity) return has(s, *quantity);
  for (std::size_t q = 0; q < kQuantityCount; ++q) {
    if (has(s, static_cast<Quantity>(q))) return true;
  }
  return false;
}

const TrackView::Extent& TrackView::extent() const {
  if (!extent_) {
    Extent e;
    Reader r = reader();
    for (TrackSample s; r.next(s);) {
      if (e.size++ == 0) e.first_ns = s.time_ns;
      e.last_ns = s.time_ns;
    }
    extent_ = e;
  }
  return *extent_;
}

bool TrackView::Reader::next(TrackSample& out) {
  while (reader_.next(out)) {
    if (filter_.matches(out)) return true;
  }
  return false;
}

std::optional<TrackSample> TrackView::front() const {
  Reader r = reader();
  if (TrackSample s; r.next(s)) return s;
  return std::nullopt;
}

}  // namespace navfuse::apps::bench

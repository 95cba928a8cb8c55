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

std::vector<const TrackSample*> SolutionTrack::with(Quantity q, bool navigating_only) const {
  std::vector<const TrackSample*> out;
  for (const TrackSample& s : samples_) {
    if (has(s, q) && (!navigating_only || is_navigating(s.mode))) out.push_back(&s);
  }
  return out;
}

std::vector<const TrackSample*> SolutionTrack::with_any() const {
  std::vector<const TrackSample*> out;
  for (const TrackSample& s : samples_) {
    for (std::size_t q = 0; q < kQuantityCount; ++q) {
      if (has(s, static_cast<Quantity>(q))) {
        out.push_back(&s);
        break;
      }
    }
  }
  return out;
}

}  // namespace navfuse::apps::bench

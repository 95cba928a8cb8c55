#include "apps/bench/truth_reference.hpp"

#include <limits>

namespace navfuse::apps::bench {

TrackSample track_sample_from(const TruthPoint& p) {
  TrackSample s;
  s.time_ns = p.time_ns;
  s.mode = NavMode::kNavigation;
  s.valid = NavSolution::kValidPosition | (p.has_velocity ? NavSolution::kValidVelocity : 0u) |
            (p.has_attitude ? NavSolution::kValidAttitude | NavSolution::kValidHeading : 0u);
  if (!p.gnss_available) s.status_flags |= NavSolution::kStatusGnssOutage;
  if (p.stationary) s.status_flags |= NavSolution::kStatusStationary;
  s.lat_rad = p.lat_rad;
  s.lon_rad = p.lon_rad;
  s.height_m = p.height_m;
  s.vel_ned_mps = p.vel_ned_mps;
  s.rpy_rad = p.rpy_rad;
  return s;
}

std::optional<TrackSample> TruthReference::at(std::int64_t time_ns, TrackInterpolator::Miss* miss) {
  const std::optional<TruthPoint> p = track_.at(time_ns);
  if (miss != nullptr) *miss = p ? TrackInterpolator::Miss::kNone : TrackInterpolator::Miss::kOutside;
  if (!p) return std::nullopt;
  return track_sample_from(*p);
}

SolutionTrack TruthReference::epochs() {
  SolutionTrack track;
  while (const auto p = track_.next_until(std::numeric_limits<std::int64_t>::max())) track.append(track_sample_from(*p));
  return track;
}

std::optional<PhaseLabel> TruthReference::phase_at(std::int64_t time_ns) {
  const std::optional<TruthPoint> p = track_.at(time_ns);
  if (!p) return std::nullopt;
  return PhaseLabel{.gnss_outage = !p->gnss_available, .stationary = p->stationary};
}

}  // namespace navfuse::apps::bench

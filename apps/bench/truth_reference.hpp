// Truth as a bench solution: the reference (navfuse truth CSV, RTKLIB .pos, KF-GINS .nav) read
// and interpolated by replay's TruthTrack (so that bench and `navfuse replay --truth` see exactly
// the same truth values), presented as TrackSamples (the quantities the reference has, no
// uncertainty) and phase labels.
//
// TruthTrack streams the file and answers only increasing query times; every pass over a
// solution therefore opens its own TruthReference.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "apps/bench/phase_timeline.hpp"
#include "apps/bench/solution_track.hpp"
#include "apps/bench/time_alignment.hpp"
#include "apps/replay/truth_track.hpp"

namespace navfuse::apps::bench {

class TruthReference {
 public:
  // Throws CommandError naming the file when it is missing or not a truth CSV.
  explicit TruthReference(const std::string& path) : track_(path) {}

  // Truth at `time_ns` (increasing between calls); nullopt outside the file (miss: kOutside).
  std::optional<TrackSample> at(std::int64_t time_ns, TrackInterpolator::Miss* miss = nullptr);
  // The phase at `time_ns` with the truth sample it came from.
  std::optional<PhaseLabel> phase_at(std::int64_t time_ns);
  // Every row of a sparse reference (compared at its own epochs); not to be mixed with at().
  SolutionTrack epochs();
  ReferencePoint point() const { return track_.point(); }
  bool sparse() const { return track_.sparse(); }

 private:
  TruthTrack track_;
};

TrackSample track_sample_from(const TruthPoint& p);

}  // namespace navfuse::apps::bench

// When the vehicle was in which phase of a run, for splitting `navfuse bench` errors and shading
// the report's plots: GNSS available or in an outage, stationary or moving.
//
// The timeline is a step function over label points in time order: a label holds from its point
// until the next one. It comes from truth when the user gives one (the simulator's
// gnss_available / stationary columns: the real phases), otherwise from the log itself:
//  - GNSS outage: no GNSS position fix (2-D or better, from any input) in the last
//    max(1 s, 2.5 fix intervals). A receiver's own dead-reckoned fix is not a fix.
//  - stationary: navfuse's own zero-velocity detection (NavSolution::kStatusStationary), the
//    only motion test on the log that does not depend on a solution's errors.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace navfuse::apps::bench {

struct PhaseLabel {
  bool gnss_outage = false;
  bool stationary = false;
};

struct TimeInterval {
  std::int64_t start_ns = 0;
  std::int64_t end_ns = 0;
};

class PhaseTimeline {
 public:
  explicit PhaseTimeline(std::string source = "log") : source_(std::move(source)) {}

  // Points must come in increasing time order; an earlier or equal time is ignored.
  void add(std::int64_t time_ns, PhaseLabel label);

  // The label in effect at `time_ns` (before the first point: the first point's); nullopt when
  // the timeline is empty.
  std::optional<PhaseLabel> at(std::int64_t time_ns) const;

  // Maximal runs of points with gnss_outage (or stationary) set. A run ends at the first point
  // without the flag, or at the last point.
  std::vector<TimeInterval> outages() const { return runs(&PhaseLabel::gnss_outage); }
  std::vector<TimeInterval> stationary_periods() const { return runs(&PhaseLabel::stationary); }

  const std::string& source() const { return source_; }  // "truth" or "log"
  bool empty() const { return times_.empty(); }

 private:
  std::vector<TimeInterval> runs(bool PhaseLabel::*flag) const;

  std::string source_;
  std::vector<std::int64_t> times_;
  std::vector<PhaseLabel> labels_;
};

// The age beyond which the last GNSS fix no longer counts as "GNSS available": max(1 s, 2.5
// median fix intervals). `fix_times_ns` sorted.
std::int64_t max_fix_age_ns(const std::vector<std::int64_t>& fix_times_ns);

// True when no fix lies in [time_ns - max_age_ns, time_ns]. `fix_times_ns` sorted.
bool in_gnss_outage(const std::vector<std::int64_t>& fix_times_ns, std::int64_t time_ns, std::int64_t max_age_ns);

}  // namespace navfuse::apps::bench

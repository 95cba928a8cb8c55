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
//
// The label points (one per navfuse pose) are kept on disk (apps/common/spill_file.hpp) and read
// back by cursors at increasing times; the outage and stationary intervals are built as points are
// added. The GNSS fix times are sorted externally. Memory does not grow with the log.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "apps/bench/forward_cursor.hpp"
#include "apps/common/external_sort.hpp"
#include "apps/common/spill_file.hpp"

namespace navfuse::apps::bench {

struct PhaseLabel {
  bool gnss_outage = false;
  bool stationary = false;
};

// One label point as stored.
struct PhasePointRecord {
  std::int64_t time_ns = 0;
  PhaseLabel label;
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

  // Reads the labels at non-decreasing times (an earlier time restarts from the first point).
  // The timeline must outlive the cursor.
  class Cursor {
   public:
    // The label in effect at `time_ns` (before the first point: the first point's); nullopt when
    // the timeline is empty.
    std::optional<PhaseLabel> at(std::int64_t time_ns);

   private:
    friend class PhaseTimeline;
    static std::int64_t time_of(const PhasePointRecord& p) { return p.time_ns; }
    using Points = ForwardCursor<SpillFile<PhasePointRecord>::Reader, PhasePointRecord, decltype(&time_of)>;
    explicit Cursor(const PhaseTimeline& timeline)
        : timeline_(&timeline), points_(timeline.points_.reader(), &time_of) {}
    const PhaseTimeline* timeline_;
    Points points_;
    std::optional<std::int64_t> last_asked_ns_;
  };
  Cursor cursor() const { return Cursor(*this); }

  // Maximal runs of points with gnss_outage (or stationary) set. A run ends at the first point
  // without the flag, or at the last point.
  std::vector<TimeInterval> outages() const { return outages_.intervals(last_ns_); }
  std::vector<TimeInterval> stationary_periods() const { return stationary_.intervals(last_ns_); }

  const std::string& source() const { return source_; }  // "truth" or "log"
  bool empty() const { return points_.empty(); }

 private:
  // The runs of one flag, built point by point.
  struct Runs {
    std::vector<TimeInterval> closed;
    std::optional<std::int64_t> open_since_ns;
    void add(std::int64_t time_ns, bool on);
    std::vector<TimeInterval> intervals(std::int64_t last_ns) const;
  };

  std::string source_;
  SpillFile<PhasePointRecord> points_{4096};
  std::int64_t last_ns_ = 0;
  Runs outages_, stationary_;
};

// Whether GNSS was in an outage at a time, from the log's fix times: the age beyond which the last
// fix no longer counts as "GNSS available" is max(1 s, 2.5 median fix intervals).
class GnssOutageDetector {
 public:
  // `fix_times_ns` must outlive the detector.
  explicit GnssOutageDetector(const ExternalSort<std::int64_t>& fix_times_ns);

  std::int64_t max_fix_age_ns() const { return max_age_ns_; }
  // True when no fix lies in [time_ns - max_fix_age_ns, time_ns]. Cheapest at non-decreasing
  // times (an earlier time restarts from the first fix).
  bool at(std::int64_t time_ns);

 private:
  static std::int64_t time_of(const std::int64_t& t) { return t; }
  using Fixes = ForwardCursor<ExternalSort<std::int64_t>::Reader, std::int64_t, decltype(&time_of)>;

  const ExternalSort<std::int64_t>* fix_times_ns_;
  std::int64_t max_age_ns_;
  Fixes fixes_;  // last(): the last fix at or before the last time asked
  std::optional<std::int64_t> last_asked_ns_;
};

}  // namespace navfuse::apps::bench

// One compared pair of `navfuse bench` (navfuse_vs_device, navfuse_vs_truth, device_vs_truth):
// the aligned errors over time (for the CSV and the plots) and their statistics (for
// metrics.json), with the count of times that could not be aligned.
//
// The comparison runs at the times of one solution (the "sampled" one) and looks the other up at
// those times, interpolating it (time_alignment.hpp) or reading truth. Bench samples at the
// device's times against navfuse (devices often report slower than navfuse's output rate, and
// interpolating the denser track loses least) and at each solution's own times against truth
// (as replay does).
//
// The aligned errors go to a temporary file (apps/common/spill_file.hpp) as they are computed
// and the statistics are exact without holding the values (apps/replay/error_stats.hpp): a
// comparison's memory does not grow with the log.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/bench/error_metrics.hpp"
#include "apps/bench/phase_split.hpp"
#include "apps/bench/phase_timeline.hpp"
#include "apps/bench/solution_track.hpp"
#include "apps/bench/time_alignment.hpp"

namespace navfuse::apps::bench {

// One aligned time of a pair: the errors and the phase there (nullopt: unknown).
struct AlignedError {
  SolutionError error;
  std::optional<PhaseLabel> phase;
};

}  // namespace navfuse::apps::bench

// Plain values (Eigen fixed-size vectors are arrays of doubles): spilled as bytes.
template <>
inline constexpr bool navfuse::apps::kSpillableAsBytes<navfuse::apps::bench::AlignedError> = true;

namespace navfuse::apps::bench {

struct PairSpec {
  std::string name;       // "navfuse_vs_device": the metrics.json key and the CSV file stem
  std::string estimate;   // "navfuse", "device"
  std::string reference;  // "device", "truth"
  bool reference_is_truth = false;
  bool sampled_is_estimate = true;  // which side the sampled solution is on
};

// The other solution at a time; nullopt (with the reason) when it cannot be had there.
using SolutionLookup = std::function<std::optional<TrackSample>(std::int64_t time_ns, TrackInterpolator::Miss* miss)>;

struct PairComparison {
  PairSpec spec;
  SpillFile<AlignedError> errors{512};  // aligned times, in time order
  PhasedMetrics metrics;
  std::uint64_t outside = 0;  // sampled times outside the other solution's span
  std::uint64_t gaps = 0;     // sampled times inside a gap of the other solution
  std::uint64_t no_common_quantity = 0;  // aligned, but nothing both solutions carry

  std::size_t samples() const { return metrics.all().samples(); }
  double overlap_s() const { return metrics.all().span_s(); }

  // The metrics.json object: {"estimate", "reference", "samples", "overlap_s", "horizontal_m":
  // {rms, p50, p95, p99, max, samples}, ... "consistency", "by_phase", "by_mode", "unaligned"}.
  nlohmann::ordered_json to_json() const;
};

// `other` is asked at the sampled times, in increasing order.
PairComparison compare_pair(const PairSpec& spec, const TrackView& sampled, const SolutionLookup& other,
                            const PhaseTimeline& phases);

// A lookup into a solution track by interpolation (`track` must outlive it).
SolutionLookup interpolating_lookup(TrackInterpolator& track);

}  // namespace navfuse::apps::bench

// Accuracy of the poses of a replay against the simulator's truth (`navfuse replay --truth`):
// at every pose output time with a navigation solution (modes navigation and dead reckoning),
// the truth is interpolated to the pose time and the errors are collected:
//   horizontal_m   north/east distance (local NED at the truth point, core geodesy)
//   vertical_m     |height difference|
//   velocity_mps   |3-D NED velocity difference|
//   roll_deg, pitch_deg, heading_deg   |wrapped angle difference|
// separately also over the poses inside GNSS outages (the truth's gnss_available = 0), where the
// errors show how well the filter dead-reckons. The result is the summary's "accuracy" section.
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/replay/error_stats.hpp"
#include "apps/replay/truth_track.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

class TruthAccuracy {
 public:
  explicit TruthAccuracy(const std::string& truth_path) : truth_(truth_path) {}

  // Called at each pose time (times increasing).
  void add(const NavSolution& s);

  // {"truth", "samples", "overlap_s", "horizontal_m": {rms, p50, p95, p99, max}, ...,
  //  "gnss_outage": {"samples", "horizontal_m", "vertical_m", ...}}
  nlohmann::ordered_json to_json() const;
  void print(std::ostream& os) const;

  enum Metric { kHorizontal = 0, kVertical, kVelocity, kRoll, kPitch, kHeading, kMetricCount };
  static const char* metric_name(int metric);
  ErrorSummary summary(int metric, bool outage_only = false) const;
  std::size_t samples() const { return all_[0].size(); }

 private:
  TruthTrack truth_;
  std::array<ErrorStats, kMetricCount> all_;
  std::array<ErrorStats, kMetricCount> outage_;
  std::int64_t first_ns_ = 0, last_ns_ = 0;
  std::uint64_t poses_without_truth_ = 0;
};

}  // namespace navfuse::apps

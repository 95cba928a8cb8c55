// Errors of one navigation solution (the estimate) against another (the reference) at aligned
// times, and their statistics, for `navfuse bench` metrics.json.
//
// SHARED WITH `navfuse replay --truth`: the per-sample error definitions below are the ones
// apps/replay/truth_accuracy.cpp uses (horizontal distance in the reference's local NED, absolute
// height difference, 3-D velocity difference, wrapped angle differences), and the statistics are
// apps/replay/error_stats.hpp's ErrorStats (nearest-rank percentiles), so bench's
// navfuse_vs_truth numbers equal replay's accuracy numbers on the same log (a test checks it).
// Code that needs signed per-axis errors, sigma consistency or phase splits should call
// solution_error() / MetricSet here rather than re-derive them.
//
// Signs: error = estimate - reference, position and velocity in the reference's NED frame, angles
// wrapped to [-180, 180) deg so that headings of 179 and -179 deg differ by 2 deg, not 358.
//
// Consistency: how often |error| on one axis is within k = 1, 2, 3 sigma, sigma being what the
// solutions report about themselves: the estimate's 1-sigma against truth, and the root sum of
// squares of both solutions' sigmas when neither is truth (treating them as independent, which
// they are not quite when both fuse the same GNSS: the fraction is then a little optimistic).
// For a Gaussian error with an honest sigma the fractions are 68.3 %, 95.4 % and 99.7 %.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "apps/bench/solution_track.hpp"
#include "apps/replay/error_stats.hpp"

namespace navfuse::apps::bench {

// The errors at one aligned time. A quantity either solution lacks is absent (has[q] false).
struct SolutionError {
  std::int64_t time_ns = 0;
  NavMode estimate_mode = NavMode::kInvalid;
  std::array<bool, kQuantityCount> has{};
  Eigen::Vector3d position_ned_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();  // roll, pitch (with kAttitude), yaw (kHeading)
  // 1-sigma of each error axis (same layout); NaN where a solution reports no uncertainty.
  Eigen::Vector3d position_sigma_m = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d velocity_sigma_mps = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d rpy_sigma_rad = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());

  bool any() const { return has[0] || has[1] || has[2] || has[3]; }
};

// Errors of `estimate` against `reference` (same time). `reference_is_truth`: the reference's
// own sigma is ignored (truth has none).
SolutionError solution_error(const TrackSample& estimate, const TrackSample& reference, bool reference_is_truth);

// Scalar error metrics, in metrics.json order. The first six are the DESIGN.md contract keys.
enum class Metric : std::uint8_t {
  kHorizontal = 0,  // horizontal_m   |north, east|
  kVertical,        // vertical_m     |down|
  kVelocity,        // velocity_mps   |3-D velocity error|
  kRoll,            // roll_deg       |roll error|
  kPitch,           // pitch_deg      |pitch error|
  kHeading,         // heading_deg    |wrapped yaw error|
  kPosition3d,      // position_3d_m  |3-D position error|
  kCount
};
inline constexpr std::size_t kMetricCount = static_cast<std::size_t>(Metric::kCount);
std::string_view metric_key(Metric m);

// The per-axis errors checked for consistency, in metrics.json order.
enum class Axis : std::uint8_t {
  kNorth = 0, kEast, kDown, kVelNorth, kVelEast, kVelDown, kRoll, kPitch, kHeading, kCount
};
inline constexpr std::size_t kAxisCount = static_cast<std::size_t>(Axis::kCount);
std::string_view axis_key(Axis a);

// The value of a metric for one aligned time, if the quantity it needs is present.
std::optional<double> metric_value(const SolutionError& e, Metric m);
// Signed error and sigma of one axis (sigma NaN when unknown), if present.
std::optional<std::pair<double, double>> axis_error(const SolutionError& e, Axis a);

struct ConsistencyCount {
  std::uint64_t samples = 0;  // errors with a known sigma
  std::array<std::uint64_t, 3> within{};  // |error| <= 1, 2, 3 sigma
};

// Statistics of a set of aligned errors: the distribution of every metric and the consistency
// of every axis.
class MetricSet {
 public:
  void add(const SolutionError& e);

  std::size_t samples() const { return samples_; }
  // Time from the first to the last sample added (0 when fewer than two).
  double span_s() const;
  ErrorSummary summary(Metric m) const { return stats_[static_cast<std::size_t>(m)].summary(); }
  const ConsistencyCount& consistency(Axis a) const { return consistency_[static_cast<std::size_t>(a)]; }

  // {"samples", "span_s", "horizontal_m": {rms, p50, p95, p99, max, samples}, ...}
  nlohmann::ordered_json metrics_json() const;
  // {"position_north": {"samples", "within_1sigma", "within_2sigma", "within_3sigma"}, ...}:
  // fractions in [0, 1]; axes without any sigma are left out.
  nlohmann::ordered_json consistency_json() const;

 private:
  std::size_t samples_ = 0;
  std::int64_t first_ns_ = 0, last_ns_ = 0;
  std::array<ErrorStats, kMetricCount> stats_;
  std::array<ConsistencyCount, kAxisCount> consistency_{};
};

}  // namespace navfuse::apps::bench

// Accuracy of the poses of a replay against a reference (`navfuse replay --truth`: navfuse's
// truth CSV, an RTKLIB .pos or a KF-GINS .nav; truth_rows.hpp). For every comparison with a
// navigation solution (modes navigation and dead reckoning) the errors collected are:
//   horizontal_m   north/east distance (local NED at the reference point, core geodesy)
//   vertical_m     |height difference|
//   velocity_mps   |3-D NED velocity difference|             (when the reference has velocity)
//   roll_deg, pitch_deg, heading_deg   |wrapped angle difference|  (when it has attitude)
// separately also over the poses inside GNSS outages (the truth's gnss_available = 0), where the
// errors show how well the filter dead-reckons. The result is the summary's "accuracy" section.
//
// Where: a reference at the IMU (csv, nav) is compared with the solution as it is; one at the
// GNSS antenna (rtklib) with the solution moved to the antenna by gnss.lever_arm_m (position
// + C_nb l, velocity + C_nb (w x l)), so the lever arm is not counted as error.
// When: a dense reference is interpolated at every pose; a sparse one (rtklib) is compared at
// each of its epochs with the first navigation pose at or after it (at most kMaxPoseGapNs later),
// moved back along its velocity: the estimate that includes what was measured at the epoch, as
// filters that update at GNSS epochs (KF-GINS) report it. Interpolating from the pose before
// would score the prediction, not the estimate.
#pragma once

#include <array>
#include <map>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "apps/fusion/gnss_outage_plan.hpp"
#include "apps/replay/error_stats.hpp"
#include "apps/replay/truth_track.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

class TruthAccuracy {
 public:
  static constexpr std::int64_t kMaxPoseGapNs = 100'000'000;

  explicit TruthAccuracy(const std::string& truth_argument,
                         const Eigen::Vector3d& antenna_lever_arm_m = Eigen::Vector3d::Zero())
      : truth_(truth_argument), lever_arm_m_(antenna_lever_arm_m) {}

  // Called at each pose time (times increasing).
  void add(const NavSolution& s);
  // replay --gnss-outage: comparisons inside the plan's windows count as outage (instead of the
  // truth's gnss_available flag), and the horizontal error of the last comparison in each window
  // is kept as that outage's end-of-outage error. Call before the first add().
  void use_outage_plan(const GnssOutagePlan& plan, std::int64_t first_imu_ns);

  // {"samples", "overlap_s", "reference": {...}, "horizontal_m": {rms, p50, p95, p99, max}, ...,
  //  "gnss_outage": {"samples", "horizontal_m", "vertical_m", ...}}
  nlohmann::ordered_json to_json() const;
  void print(std::ostream& os) const;

  enum Metric { kHorizontal = 0, kVertical, kVelocity, kRoll, kPitch, kHeading, kMetricCount };
  static const char* metric_name(int metric);
  ErrorSummary summary(int metric, bool outage_only = false) const;
  std::size_t samples() const { return all_[0].size(); }

 private:
  void score(const NavSolution& s, const TruthPoint& t);
  void add_sparse(const NavSolution& s);

  TruthTrack truth_;
  Eigen::Vector3d lever_arm_m_;
  std::array<ErrorStats, kMetricCount> all_;
  std::array<ErrorStats, kMetricCount> outage_;
  std::int64_t first_ns_ = 0, last_ns_ = 0;
  std::uint64_t poses_without_truth_ = 0;
  std::uint64_t epochs_unscored_ = 0;  // sparse reference epochs with no navigation pose around them
  std::optional<NavSolution> previous_;  // last navigation pose (sparse references)
  std::optional<GnssOutagePlan> plan_;
  std::int64_t plan_first_ns_ = 0;
  std::map<std::int64_t, double> outage_end_horizontal_m_;  // by window end: the last error in it
};

}  // namespace navfuse::apps

#include "apps/replay/truth_accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

double angle_error_deg(double a_rad, double b_rad) {
  return std::abs(std::remainder(a_rad - b_rad, 2.0 * rot::kPi)) * rot::kRadToDeg;
}

bool navigating(const NavSolution& s) {
  return s.mode == NavMode::kNavigation || s.mode == NavMode::kDeadReckoning || s.mode == NavMode::kSmoothed;
}

// The first pose at or after an epoch `t`, moved back along its velocity to `t`: the filter's
// estimate at the epoch including anything measured at it (a fix at t is fused at the IMU sample
// nearest t, so the pose before may still be the prediction). Over one IMU interval the
// velocity change is second order (a walker's 2 m/s^2 over 10 ms: 0.1 mm).
NavSolution moved_back(const NavSolution& s, std::int64_t t) {
  NavSolution out = s;
  const double dt = static_cast<double>(t - s.header.time_ns) * 1e-9;  // <= 0
  const geo::Llh llh = geo::llh_offset({s.lat_rad, s.lon_rad, s.height_m}, s.vel_ned_mps * dt);
  out.lat_rad = llh.lat_rad;
  out.lon_rad = llh.lon_rad;
  out.height_m = llh.height_m;
  out.header.time_ns = t;
  return out;
}

}  // namespace

const char* TruthAccuracy::metric_name(int metric) {
  static constexpr const char* kNames[kMetricCount] = {"horizontal_m", "vertical_m", "velocity_mps",
                                                       "roll_deg",     "pitch_deg",  "heading_deg"};
  return kNames[metric];
}

void TruthAccuracy::add(const NavSolution& s) {
  if (truth_.sparse()) {
    add_sparse(s);
    return;
  }
  if (!navigating(s)) return;
  const auto t = truth_.at(s.header.time_ns);
  if (!t) {
    ++poses_without_truth_;
    return;
  }
  score(s, *t);
}

void TruthAccuracy::add_sparse(const NavSolution& s) {
  const bool usable = navigating(s);
  while (const auto row = truth_.next_until(s.header.time_ns)) {
    if (usable && previous_ && s.header.time_ns - row->time_ns <= kMaxPoseGapNs) {
      score(moved_back(s, row->time_ns), *row);
    } else {
      ++epochs_unscored_;
    }
  }
  if (usable) {
    previous_ = s;
  } else {
    previous_.reset();
  }
}

void TruthAccuracy::score(const NavSolution& imu_point, const TruthPoint& t) {
  NavSolution s = imu_point;
  if (truth_.point() == ReferencePoint::kAntenna) {
    const Eigen::Matrix3d c_nb = rot::dcm_from_rpy(s.rpy_rad);
    const geo::Llh antenna = geo::llh_offset({s.lat_rad, s.lon_rad, s.height_m}, c_nb * lever_arm_m_);
    s.lat_rad = antenna.lat_rad;
    s.lon_rad = antenna.lon_rad;
    s.height_m = antenna.height_m;
    s.vel_ned_mps += c_nb * s.angular_rate_rps.cross(lever_arm_m_);
  }
  const Eigen::Vector3d d_ned =
      geo::ned_offset_m({t.lat_rad, t.lon_rad, t.height_m}, {s.lat_rad, s.lon_rad, s.height_m});
  const std::array<double, kMetricCount> e = {
      std::hypot(d_ned.x(), d_ned.y()),
      std::abs(s.height_m - t.height_m),
      (s.vel_ned_mps - t.vel_ned_mps).norm(),
      angle_error_deg(s.rpy_rad.x(), t.rpy_rad.x()),
      angle_error_deg(s.rpy_rad.y(), t.rpy_rad.y()),
      angle_error_deg(s.rpy_rad.z(), t.rpy_rad.z())};
  const std::array<bool, kMetricCount> have = {true, true, t.has_velocity, t.has_attitude, t.has_attitude,
                                               t.has_attitude};
  if (all_[0].size() == 0) first_ns_ = s.header.time_ns;
  last_ns_ = s.header.time_ns;
  bool in_outage = !t.gnss_available;
  if (plan_) {
    in_outage = plan_->in_outage(s.header.time_ns, plan_first_ns_);
    if (in_outage) outage_end_horizontal_m_[plan_->outage_end_ns(s.header.time_ns, plan_first_ns_)] = e[kHorizontal];
  }
  for (int m = 0; m < kMetricCount; ++m) {
    if (!have[m]) continue;
    all_[m].add(e[m]);
    if (in_outage) outage_[m].add(e[m]);
  }
}

void TruthAccuracy::use_outage_plan(const GnssOutagePlan& plan, std::int64_t first_imu_ns) {
  plan_ = plan;
  plan_first_ns_ = first_imu_ns;
}

ErrorSummary TruthAccuracy::summary(int metric, bool outage_only) const {
  return (outage_only ? outage_ : all_)[metric].summary();
}

nlohmann::ordered_json TruthAccuracy::to_json() const {
  nlohmann::ordered_json j;
  j["samples"] = samples();
  j["overlap_s"] = samples() ? static_cast<double>(last_ns_ - first_ns_) * 1e-9 : 0.0;
  j["poses_without_truth"] = poses_without_truth_;
  j["reference"] = {{"format", truth_.format()},
                    {"point", truth_.point() == ReferencePoint::kAntenna ? "antenna" : "imu"},
                    {"rows", truth_.rows_read()},
                    {"rows_not_fixed_skipped", truth_.rows_skipped()},
                    {"epochs_unscored", epochs_unscored_}};
  for (int m = 0; m < kMetricCount; ++m) {
    if (all_[m].size() > 0 || m == kHorizontal) j[metric_name(m)] = apps::to_json(summary(m));
  }
  nlohmann::ordered_json o;
  o["samples"] = outage_[0].size();
  for (int m = 0; m < kMetricCount; ++m) {
    if (all_[m].size() > 0 || m == kHorizontal) o[metric_name(m)] = apps::to_json(summary(m, true));
  }
  if (plan_) {
    double sum = 0.0, worst = 0.0;
    nlohmann::ordered_json each = nlohmann::ordered_json::array();
    for (const auto& [end_ns, e] : outage_end_horizontal_m_) {
      sum += e;
      worst = std::max(worst, e);
      each.push_back({{"end_time_s", static_cast<double>(end_ns) * 1e-9}, {"horizontal_m", e}});
    }
    const std::size_t n = outage_end_horizontal_m_.size();
    o["end_of_outage_horizontal_m"] = {
        {"outages", n}, {"mean", n ? sum / static_cast<double>(n) : 0.0}, {"max", worst}, {"each", each}};
  }
  j["gnss_outage"] = o;
  return j;
}

void TruthAccuracy::print(std::ostream& os) const {
  char line[160];
  os << "accuracy against " << truth_.format() << " reference at the "
     << (truth_.point() == ReferencePoint::kAntenna ? "antenna" : "IMU");
  if (samples() == 0) {
    // Rows of zeros would read as a perfect score.
    os << ": no poses in navigation to score\n";
    return;
  }
  os << " (" << samples()
     << (truth_.sparse() ? " reference epochs" : " poses") << " in navigation";
  if (outage_[0].size() > 0) os << ", " << outage_[0].size() << " of them in GNSS outages";
  os << "):\n";
  std::snprintf(line, sizeof line, "  %-14s %10s %10s %10s %10s %10s\n", "", "rms", "p50", "p95", "p99", "max");
  os << line;
  const auto row = [&](const char* label, const ErrorSummary& e) {
    std::snprintf(line, sizeof line, "  %-14s %10.3f %10.3f %10.3f %10.3f %10.3f\n", label, e.rms, e.p50, e.p95,
                  e.p99, e.max);
    os << line;
  };
  for (int m = 0; m < kMetricCount; ++m) {
    if (all_[m].size() > 0 || m == kHorizontal) row(metric_name(m), summary(m));
  }
  if (outage_[0].size() > 0) {
    row("outage horiz_m", summary(kHorizontal, true));
    row("outage vert_m", summary(kVertical, true));
  }
  if (plan_ && !outage_end_horizontal_m_.empty()) {
    double sum = 0.0, worst = 0.0;
    for (const auto& [end_ns, e] : outage_end_horizontal_m_) {
      sum += e;
      worst = std::max(worst, e);
    }
    std::snprintf(line, sizeof line, "  end of outage: horizontal error mean %.3f m, max %.3f m over %zu outages\n",
                  sum / static_cast<double>(outage_end_horizontal_m_.size()), worst, outage_end_horizontal_m_.size());
    os << line;
  }
}

}  // namespace navfuse::apps

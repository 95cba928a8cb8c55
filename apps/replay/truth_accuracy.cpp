#include "apps/replay/truth_accuracy.hpp"

#include <cmath>
#include <cstdio>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

double angle_error_deg(double a_rad, double b_rad) {
  return std::abs(std::remainder(a_rad - b_rad, 2.0 * rot::kPi)) * rot::kRadToDeg;
}

}  // namespace

const char* TruthAccuracy::metric_name(int metric) {
  static constexpr const char* kNames[kMetricCount] = {"horizontal_m", "vertical_m", "velocity_mps",
                                                       "roll_deg",     "pitch_deg",  "heading_deg"};
  return kNames[metric];
}

void TruthAccuracy::add(const NavSolution& s) {
  if (s.mode != NavMode::kNavigation && s.mode != NavMode::kDeadReckoning) return;
  const auto t = truth_.at(s.header.time_ns);
  if (!t) {
    ++poses_without_truth_;
    return;
  }
  const Eigen::Vector3d d_ned =
      geo::ned_offset_m({t->lat_rad, t->lon_rad, t->height_m}, {s.lat_rad, s.lon_rad, s.height_m});
  const std::array<double, kMetricCount> e = {
      std::hypot(d_ned.x(), d_ned.y()),
      std::abs(s.height_m - t->height_m),
      (s.vel_ned_mps - t->vel_ned_mps).norm(),
      angle_error_deg(s.rpy_rad.x(), t->rpy_rad.x()),
      angle_error_deg(s.rpy_rad.y(), t->rpy_rad.y()),
      angle_error_deg(s.rpy_rad.z(), t->rpy_rad.z())};
  if (all_[0].size() == 0) first_ns_ = s.header.time_ns;
  last_ns_ = s.header.time_ns;
  for (int m = 0; m < kMetricCount; ++m) {
    all_[m].add(e[m]);
    if (!t->gnss_available) outage_[m].add(e[m]);
  }
}

ErrorSummary TruthAccuracy::summary(int metric, bool outage_only) const {
  return (outage_only ? outage_ : all_)[metric].summary();
}

nlohmann::ordered_json TruthAccuracy::to_json() const {
  nlohmann::ordered_json j;
  j["samples"] = samples();
  j["overlap_s"] = samples() ? static_cast<double>(last_ns_ - first_ns_) * 1e-9 : 0.0;
  j["poses_without_truth"] = poses_without_truth_;
  for (int m = 0; m < kMetricCount; ++m) j[metric_name(m)] = apps::to_json(summary(m));
  nlohmann::ordered_json o;
  o["samples"] = outage_[0].size();
  for (int m = 0; m < kMetricCount; ++m) o[metric_name(m)] = apps::to_json(summary(m, true));
  j["gnss_outage"] = o;
  return j;
}

void TruthAccuracy::print(std::ostream& os) const {
  char line[160];
  os << "accuracy against truth (" << samples() << " poses in navigation";
  if (outage_[0].size() > 0) os << ", " << outage_[0].size() << " of them in GNSS outages";
  os << "):\n";
  std::snprintf(line, sizeof line, "  %-14s %10s %10s %10s %10s %10s\n", "", "rms", "p50", "p95", "p99", "max");
  os << line;
  const auto row = [&](const char* label, const ErrorSummary& e) {
    std::snprintf(line, sizeof line, "  %-14s %10.3f %10.3f %10.3f %10.3f %10.3f\n", label, e.rms, e.p50, e.p95,
                  e.p99, e.max);
    os << line;
  };
  for (int m = 0; m < kMetricCount; ++m) row(metric_name(m), summary(m));
  if (outage_[0].size() > 0) {
    row("outage horiz_m", summary(kHorizontal, true));
    row("outage vert_m", summary(kVertical, true));
  }
}

}  // namespace navfuse::apps

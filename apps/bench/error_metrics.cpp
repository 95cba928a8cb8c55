#include "apps/bench/error_metrics.hpp"

#include <cmath>
#include <limits>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps::bench {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

double wrapped_difference_rad(double estimate_rad, double reference_rad) {
  return std::remainder(estimate_rad - reference_rad, 2.0 * rot::kPi);
}

// Root sum of squares of the sigmas that apply; NaN when one that applies is unknown.
Eigen::Vector3d combined_sigma(const TrackSample& est, const TrackSample& ref, bool ref_is_truth, Quantity q,
                               const Eigen::Vector3d& est_sigma, const Eigen::Vector3d& ref_sigma) {
  if (!has_std(est, q) || (!ref_is_truth && !has_std(ref, q))) return Eigen::Vector3d::Constant(kNan);
  if (ref_is_truth) return est_sigma;
  return (est_sigma.array().square() + ref_sigma.array().square()).sqrt().matrix();
}

}  // namespace

SolutionError solution_error(const TrackSample& est, const TrackSample& ref, bool ref_is_truth) {
  SolutionError e;
  e.time_ns = ref.time_ns;
  e.estimate_mode = est.mode;
  const auto both = [&](Quantity q) { return has(est, q) && has(ref, q); };
  const auto index = [](Quantity q) { return static_cast<std::size_t>(q); };

  if (both(Quantity::kPosition)) {
    e.has[index(Quantity::kPosition)] = true;
    const Eigen::Vector3d d = geo::ned_offset_m({ref.lat_rad, ref.lon_rad, ref.height_m}, {est.lat_rad, est.lon_rad, est.height_m});
    // Down from the height difference itself, not from the NED offset (which bends with the
    // earth's curvature by d^2 / 2R): the vertical error is then exactly what replay reports.
    e.position_ned_m = {d.x(), d.y(), -(est.height_m - ref.height_m)};
    e.position_sigma_m = combined_sigma(est, ref, ref_is_truth, Quantity::kPosition, est.pos_std_ned_m, ref.pos_std_ned_m);
  }
  if (both(Quantity::kVelocity)) {
    e.has[index(Quantity::kVelocity)] = true;
    e.velocity_ned_mps = est.vel_ned_mps - ref.vel_ned_mps;
    e.velocity_sigma_mps =
        combined_sigma(est, ref, ref_is_truth, Quantity::kVelocity, est.vel_std_ned_mps, ref.vel_std_ned_mps);
  }
  const Eigen::Vector3d att_sigma =
      combined_sigma(est, ref, ref_is_truth, Quantity::kAttitude, est.att_std_rpy_rad, ref.att_std_rpy_rad);
  if (both(Quantity::kAttitude)) {
    e.has[index(Quantity::kAttitude)] = true;
    e.rpy_rad.x() = wrapped_difference_rad(est.rpy_rad.x(), ref.rpy_rad.x());
    e.rpy_rad.y() = wrapped_difference_rad(est.rpy_rad.y(), ref.rpy_rad.y());
    e.rpy_sigma_rad.head<2>() = att_sigma.head<2>();
  }
  if (both(Quantity::kHeading)) {
    e.has[index(Quantity::kHeading)] = true;
    e.rpy_rad.z() = wrapped_difference_rad(est.rpy_rad.z(), ref.rpy_rad.z());
    e.rpy_sigma_rad.z() = att_sigma.z();
  }
  return e;
}

std::string_view metric_key(Metric m) {
  switch (m) {
    case Metric::kHorizontal: return "horizontal_m";
    case Metric::kVertical: return "vertical_m";
    case Metric::kVelocity: return "velocity_mps";
    case Metric::kRoll: return "roll_deg";
    case Metric::kPitch: return "pitch_deg";
    case Metric::kHeading: return "heading_deg";
    case Metric::kPosition3d: return "position_3d_m";
    case Metric::kCount: break;
  }
  return "unknown";
}

std::string_view axis_key(Axis a) {
  switch (a) {
    case Axis::kNorth: return "position_north";
    case Axis::kEast: return "position_east";
    case Axis::kDown: return "position_down";
    case Axis::kVelNorth: return "velocity_north";
    case Axis::kVelEast: return "velocity_east";
    case Axis::kVelDown: return "velocity_down";
    case Axis::kRoll: return "roll";
    case Axis::kPitch: return "pitch";
    case Axis::kHeading: return "heading";
    case Axis::kCount: break;
  }
  return "unknown";
}

std::optional<double> metric_value(const SolutionError& e, Metric m) {
  const auto present = [&](Quantity q) { return e.has[static_cast<std::size_t>(q)]; };
  switch (m) {
    case Metric::kHorizontal:
      if (!present(Quantity::kPosition)) return std::nullopt;
      return std::hypot(e.position_ned_m.x(), e.position_ned_m.y());
    case Metric::kVertical:
      if (!present(Quantity::kPosition)) return std::nullopt;
      return std::abs(e.position_ned_m.z());
    case Metric::kPosition3d:
      if (!present(Quantity::kPosition)) return std::nullopt;
      return e.position_ned_m.norm();
    case Metric::kVelocity:
      if (!present(Quantity::kVelocity)) return std::nullopt;
      return e.velocity_ned_mps.norm();
    case Metric::kRoll:
      if (!present(Quantity::kAttitude)) return std::nullopt;
      return std::abs(e.rpy_rad.x()) * rot::kRadToDeg;
    case Metric::kPitch:
      if (!present(Quantity::kAttitude)) return std::nullopt;
      return std::abs(e.rpy_rad.y()) * rot::kRadToDeg;
    case Metric::kHeading:
      if (!present(Quantity::kHeading)) return std::nullopt;
      return std::abs(e.rpy_rad.z()) * rot::kRadToDeg;
    case Metric::kCount: break;
  }
  return std::nullopt;
}

std::optional<std::pair<double, double>> axis_error(const SolutionError& e, Axis a) {
  const auto i = static_cast<std::size_t>(a);
  if (i < 3) {
    if (!e.has[static_cast<std::size_t>(Quantity::kPosition)]) return std::nullopt;
    return std::pair{e.position_ned_m[static_cast<Eigen::Index>(i)], e.position_sigma_m[static_cast<Eigen::Index>(i)]};
  }
  if (i < 6) {
    if (!e.has[static_cast<std::size_t>(Quantity::kVelocity)]) return std::nullopt;
    const auto k = static_cast<Eigen::Index>(i - 3);
    return std::pair{e.velocity_ned_mps[k], e.velocity_sigma_mps[k]};
  }
  const Quantity q = a == Axis::kHeading ? Quantity::kHeading : Quantity::kAttitude;
  if (!e.has[static_cast<std::size_t>(q)]) return std::nullopt;
  const auto k = static_cast<Eigen::Index>(i - 6);
  return std::pair{e.rpy_rad[k], e.rpy_sigma_rad[k]};
}

void MetricSet::add(const SolutionError& e) {
  if (!e.any()) return;
  if (samples_ == 0) first_ns_ = e.time_ns;
  last_ns_ = e.time_ns;
  ++samples_;
  for (std::size_t m = 0; m < kMetricCount; ++m) {
    if (const auto v = metric_value(e, static_cast<Metric>(m))) stats_[m].add(*v);
  }
  for (std::size_t a = 0; a < kAxisCount; ++a) {
    const auto err = axis_error(e, static_cast<Axis>(a));
    if (!err || !(err->second > 0.0)) continue;  // no sigma (NaN) or a meaningless one
    ConsistencyCount& c = consistency_[a];
    ++c.samples;
    const double ratio = std::abs(err->first) / err->second;
    for (int k = 0; k < 3; ++k) {
      if (ratio <= k + 1.0) ++c.within[static_cast<std::size_t>(k)];
    }
  }
}

double MetricSet::span_s() const { return samples_ > 1 ? static_cast<double>(last_ns_ - first_ns_) * 1e-9 : 0.0; }

nlohmann::ordered_json MetricSet::metrics_json() const {
  nlohmann::ordered_json j;
  j["samples"] = samples_;
  j["span_s"] = span_s();
  for (std::size_t m = 0; m < kMetricCount; ++m) {
    const ErrorSummary s = stats_[m].summary();
    nlohmann::ordered_json o = to_json(s);
    o["samples"] = s.samples;
    j[std::string(metric_key(static_cast<Metric>(m)))] = o;
  }
  return j;
}

nlohmann::ordered_json MetricSet::consistency_json() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (std::size_t a = 0; a < kAxisCount; ++a) {
    const ConsistencyCount& c = consistency_[a];
    if (c.samples == 0) continue;
    const double n = static_cast<double>(c.samples);
    j[std::string(axis_key(static_cast<Axis>(a)))] = {{"samples", c.samples},
                                                      {"within_1sigma", static_cast<double>(c.within[0]) / n},
                                                      {"within_2sigma", static_cast<double>(c.within[1]) / n},
                                                      {"within_3sigma", static_cast<double>(c.within[2]) / n}};
  }
  return j;
}

}  // namespace navfuse::apps::bench

#include "apps/bench/bench_analysis.hpp"

#include <cstdio>

#include "apps/bench/truth_reference.hpp"
#include "apps/common/command_error.hpp"
#include "apps/common/empty_run.hpp"
#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps::bench {
namespace {

using View = TrackView;

std::int64_t gap_limit_ns(const View& view, const AnalysisOptions& options) {
  if (options.max_gap_s) return static_cast<std::int64_t>(*options.max_gap_s * 1e9);
  return default_max_gap_ns(view);
}

// "12.0 .. 345.5 s after the log start" for messages about an empty overlap.
std::string span_text(const View& view, std::int64_t start_ns) {
  if (view.empty()) return "no valid samples";
  char text[96];
  std::snprintf(text, sizeof text, "%.1f .. %.1f s after the log start",
                static_cast<double>(view.first_ns() - start_ns) * 1e-9,
                static_cast<double>(view.last_ns() - start_ns) * 1e-9);
  return text;
}

PhaseTimeline phase_timeline(const BenchLog& log, const AnalysisOptions& options,
                             SpillFile<TrackSample>& truth_at_poses) {
  SolutionTrack::Reader poses = log.navfuse.reader();
  if (!options.truth_path.empty()) {
    PhaseTimeline timeline("truth");
    TruthReference truth(options.truth_path);
    for (TrackSample pose; poses.next(pose);) {
      if (const auto t = truth.at(pose.time_ns)) {
        timeline.add(pose.time_ns, {.gnss_outage = (t->status_flags & NavSolution::kStatusGnssOutage) != 0,
                                    .stationary = (t->status_flags & NavSolution::kStatusStationary) != 0});
        truth_at_poses.push_back(*t);
      }
    }
    return timeline;
  }
  PhaseTimeline timeline("log");
  GnssOutageDetector outage(log.gnss_fix_times_ns);
  for (TrackSample pose; poses.next(pose);) {
    timeline.add(pose.time_ns, {.gnss_outage = outage.at(pose.time_ns),
                                .stationary = (pose.status_flags & NavSolution::kStatusStationary) != 0});
  }
  return timeline;
}

// navfuse's poses with their positions moved from the IMU to the GNSS antenna (+ C_nb l). The
// velocity is left at the IMU: the track has no angular rate for w x l, a few cm/s for a
// decimetre lever arm in a turn; attitude is the same at both points.
SolutionTrack moved_to_antenna(const SolutionTrack& track, const Eigen::Vector3d& lever_arm_m) {
  SolutionTrack out;
  SolutionTrack::Reader reader = track.reader();
  for (TrackSample s; reader.next(s);) {
    if ((s.valid & NavSolution::kValidPosition) != 0 && (s.valid & NavSolution::kValidAttitude) != 0) {
      const geo::Llh p = geo::llh_offset({s.lat_rad, s.lon_rad, s.height_m}, rot::dcm_from_rpy(s.rpy_rad) * lever_arm_m);
      s.lat_rad = p.lat_rad;
      s.lon_rad = p.lon_rad;
      s.height_m = p.height_m;
    }
    out.append(s);
  }
  return out;
}

void require_overlap(const PairComparison& pair, const std::string& what) {
  if (pair.samples() > 0) return;
  throw CommandError("empty overlap: " + what + " (" + std::to_string(pair.outside) + " times outside, " +
                     std::to_string(pair.gaps) + " in gaps)");
}

}  // namespace

const PairComparison* BenchAnalysis::pair(std::string_view name) const {
  for (const auto& p : pairs) {
    if (p.spec.name == name) return &p;
  }
  return nullptr;
}

// navfuse's forward poses and the device against the smoothed run, as against the device: the
// reference interpolated to the compared solution's times (the poses share the smoothed times).
void compare_with_smoothed(const BenchLog& log, const AnalysisOptions& options, const View& navfuse, const View& device,
                           BenchAnalysis& a) {
  const View smoothed = log.smoothed.with(Quantity::kPosition, /*navigating_only=*/true);
  if (smoothed.empty()) throw CommandError("empty overlap: the smoother produced no navigation solution to compare with");
  TrackInterpolator track(smoothed, gap_limit_ns(smoothed, options));
  const PairSpec navfuse_spec{.name = "navfuse_vs_smoothed", .estimate = "navfuse", .reference = "smoothed",
                              .reference_is_truth = true, .sampled_is_estimate = true};
  a.pairs.push_back(compare_pair(navfuse_spec, navfuse, interpolating_lookup(track), a.phases));
  require_overlap(a.pairs.back(), "the smoothed solution (" + span_text(smoothed, log.start_ns) +
                                      ") never overlaps navfuse's navigation solution");
  if (log.device.empty()) return;
  const PairSpec device_spec{.name = "device_vs_smoothed", .estimate = "device", .reference = "smoothed",
                             .reference_is_truth = true, .sampled_is_estimate = true};
  a.pairs.push_back(compare_pair(device_spec, device, interpolating_lookup(track), a.phases));
  require_overlap(a.pairs.back(), "the smoothed solution (" + span_text(smoothed, log.start_ns) +
                                      ") never overlaps the device solution (" + span_text(device, log.start_ns) + ")");
}

BenchAnalysis analyse(const BenchLog& log, const AnalysisOptions& options) {
  const bool with_truth = !options.truth_path.empty();
  if (with_truth && log.time_source != TimeSource::kGps) {
    throw CommandError("mismatched time bases: the truth file is in GPS time but the log's IMU is timed by " +
                       std::string(to_string(log.time_source)) + "; truth can only be compared with a GPS-timed log");
  }
  BenchAnalysis a;
  a.phases = phase_timeline(log, options, a.truth_at_poses);
  a.navfuse_timing = solution_timing(log.navfuse, log.start_ns);

  const View navfuse = log.navfuse.with(Quantity::kPosition, /*navigating_only=*/true);
  if (navfuse.empty()) {
    std::string modes;
    for (const auto& m : log.summary.run->modes_reached) modes += " " + m;
    throw nothing_useful_error("bench", "empty overlap: navfuse reached no navigation solution in the log (modes reached:" +
                                            modes + "), so there is nothing to compare");
  }
  // A device still initialising may flag fields valid that hold no solution yet (zeros): only
  // samples from a mode with an estimate are compared.
  const View device(log.device, {.quantity = std::nullopt, .navigating_only = false, .estimating_only = true});
  const bool with_device = !log.device.empty();
  if (with_device) {
    a.device_timing = solution_timing(log.device, log.start_ns);
  } else {
    a.notes.push_back("The log has no device solution (" + std::string("VN-300 INS/Attitude, CV7 0x82, UM220 ") +
                      "NAVPOS/NAVVEL/NAVATT or FusionEngine Pose): this is a navfuse-only report.");
  }
  if (log.other_device_solutions > 0) {
    a.notes.push_back(std::to_string(log.other_device_solutions) +
                      " device solutions from a second input were not compared (only the first input's are).");
  }

  if (with_device) {
    TrackInterpolator navfuse_track(navfuse, gap_limit_ns(navfuse, options));
    const PairSpec spec{.name = "navfuse_vs_device", .estimate = "navfuse", .reference = "device",
                        .reference_is_truth = false, .sampled_is_estimate = false};
    a.pairs.push_back(compare_pair(spec, device, interpolating_lookup(navfuse_track), a.phases));
    require_overlap(a.pairs.back(), "the device solution (" + span_text(device, log.start_ns) +
                                        ") never overlaps navfuse's navigation solution (" +
                                        span_text(navfuse, log.start_ns) + ")");
  }
  if (with_truth) {
    TruthReference truth(options.truth_path);
    // An antenna reference (RTKLIB) is compared with navfuse's poses moved to the antenna.
    const SolutionTrack at_antenna = truth.point() == ReferencePoint::kAntenna
                                         ? moved_to_antenna(log.navfuse, log.antenna_lever_arm_m)
                                         : SolutionTrack{};
    const View estimate =
        truth.point() == ReferencePoint::kAntenna ? at_antenna.with(Quantity::kPosition, true) : navfuse;
    if (truth.sparse()) {
      // A 1-10 Hz reference: compared at its epochs, navfuse interpolated to them.
      const SolutionTrack epochs = truth.epochs();
      TrackInterpolator navfuse_track(estimate, gap_limit_ns(estimate, options));
      const PairSpec spec{.name = "navfuse_vs_truth", .estimate = "navfuse", .reference = "truth",
                          .reference_is_truth = true, .sampled_is_estimate = false};
      a.pairs.push_back(compare_pair(spec, epochs.with_any(), interpolating_lookup(navfuse_track), a.phases));
    } else {
      const PairSpec spec{.name = "navfuse_vs_truth", .estimate = "navfuse", .reference = "truth",
                          .reference_is_truth = true, .sampled_is_estimate = true};
      a.pairs.push_back(compare_pair(
          spec, estimate, [&truth](std::int64_t t, TrackInterpolator::Miss* miss) { return truth.at(t, miss); },
          a.phases));
    }
    require_overlap(a.pairs.back(), "the truth file '" + options.truth_path + "' covers none of navfuse's navigation (" +
                                        span_text(navfuse, log.start_ns) + ")");
  }
  if (options.smoothed_reference) compare_with_smoothed(log, options, navfuse, device, a);
  if (with_truth && with_device) {
    TruthReference truth(options.truth_path);
    const PairSpec spec{.name = "device_vs_truth", .estimate = "device", .reference = "truth",
                        .reference_is_truth = true, .sampled_is_estimate = true};
    a.pairs.push_back(compare_pair(
        spec, device, [&truth](std::int64_t t, TrackInterpolator::Miss* miss) { return truth.at(t, miss); }, a.phases));
    require_overlap(a.pairs.back(), "the truth file '" + options.truth_path + "' covers none of the device solution (" +
                                        span_text(device, log.start_ns) + ")");
  }
  return a;
}

nlohmann::ordered_json BenchAnalysis::metrics_json(const BenchLog& log, const AnalysisOptions& options) const {
  nlohmann::ordered_json j;
  for (const auto& p : pairs) j[p.spec.name] = p.to_json();

  const auto seconds = [&](std::int64_t t_ns) { return static_cast<double>(t_ns - log.start_ns) * 1e-9; };
  nlohmann::ordered_json solutions;
  nlohmann::ordered_json nf = navfuse_timing.to_json();
  nf["samples"] = log.navfuse.size();
  nf["output_rate_hz"] = log.output_rate_hz;
  solutions["navfuse"] = nf;
  nlohmann::ordered_json dev;
  dev["present"] = !log.device.empty();
  if (device_timing) {
    dev["format"] = log.device_format;
    dev["samples"] = log.device.size();
    dev["out_of_order"] = log.device.dropped();
    const nlohmann::ordered_json timing = device_timing->to_json();
    for (const auto& [k, v] : timing.items()) dev[k] = v;
  }
  solutions["device"] = dev;
  if (!options.truth_path.empty()) solutions["truth"] = {{"path", options.truth_path}};
  j["solutions"] = solutions;

  nlohmann::ordered_json ph;
  ph["source"] = phases.source();
  const auto intervals = [&](const std::vector<TimeInterval>& list, double& total_s) {
    nlohmann::ordered_json arr = nlohmann::ordered_json::array();
    for (const auto& iv : list) {
      arr.push_back({seconds(iv.start_ns), seconds(iv.end_ns)});
      total_s += static_cast<double>(iv.end_ns - iv.start_ns) * 1e-9;
    }
    return arr;
  };
  double outage_s = 0.0, stationary_s = 0.0;
  ph["gnss_outages_s"] = intervals(phases.outages(), outage_s);
  ph["gnss_outage_total_s"] = outage_s;
  ph["stationary_periods_s"] = intervals(phases.stationary_periods(), stationary_s);
  ph["stationary_total_s"] = stationary_s;
  j["phases"] = ph;

  nlohmann::ordered_json lg = log.summary.to_json(/*decode_only=*/false);
  lg.erase("measurements");  // used/rejected detail belongs to replay's summary
  lg["time_source"] = std::string(to_string(log.time_source));
  lg["start_time_s"] = static_cast<double>(log.start_ns) * 1e-9;
  lg["duration_s"] = seconds(log.end_ns);
  lg["imu_samples"] = log.imu_samples;
  j["log"] = lg;
  j["notes"] = notes;
  return j;
}

}  // namespace navfuse::apps::bench

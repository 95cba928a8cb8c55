#include "apps/replay/replay.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>

#include "apps/common/command_error.hpp"
#include "apps/common/empty_run.hpp"
#include "apps/common/frontend_registry.hpp"
#include "apps/common/input_spec.hpp"
#include "apps/common/recording_format.hpp"
#include "apps/lcm/lcm_pose_writer.hpp"
#include "apps/output/csv_pose_writer.hpp"
#include "apps/output/innovation_csv_writer.hpp"
#include "apps/output/encoded_file_writer.hpp"
#include "apps/output/output_file.hpp"
#include "apps/output/output_paths.hpp"
#include "apps/output/pose_output_thread.hpp"
#include "apps/output/pose_outputs.hpp"
#include "apps/fusion/fusion_runner.hpp"
#include "apps/fusion/log_fusion.hpp"
#include "apps/fusion/measurement_merger.hpp"
#include "apps/replay/calibration_collector.hpp"
#include "apps/replay/calibration_hook.hpp"
#include "apps/replay/calibration_output.hpp"
#include "apps/replay/smoothed_pass.hpp"
#include "apps/replay/truth_accuracy.hpp"
#include "filter/engine.hpp"
#include "filter/smoother/forward_record.hpp"

namespace navfuse::apps {
namespace {

config::DeviceProfile profile_for_format(std::string_view format) {
  const frontends::FrontendInfo* f = find_frontend(format);
  return f != nullptr ? f->default_profile : config::DeviceProfile::kGeneric;
}

// Replay's use of the stream: every epoch to the writers (IMU output), and at the output rate
// a pose (FusionEngine / MIP / CSV) and a truth comparison. The writers run on their own thread
// (PoseOutputThread); the truth comparison is cheap and stays here.
class ReplayObserver final : public FusionObserver {
 public:
  ReplayObserver(PoseOutputs& outputs, TruthAccuracy* accuracy) : accuracy_(accuracy) {
    if (!outputs.empty()) writer_.emplace(outputs);
  }
  // What the observer needs filled: writers see every epoch (filled on their thread), truth
  // only poses.
  FusionRunner::Solutions solutions() const {
    if (writer_) return FusionRunner::Solutions::kDeferred;
    return accuracy_ ? FusionRunner::Solutions::kPoses : FusionRunner::Solutions::kNone;
  }
  // --gnss-outage: truth scoring marks the same windows (they start at the first IMU sample).
  void score_outages(const GnssOutagePlan& plan, const FusionRunner& runner) {
    plan_ = plan;
    runner_ = &runner;
  }
  void on_epoch(const OutputEpoch& epoch, const filter::Engine&) override {
    if (plan_ && accuracy_ && runner_->first_imu()) {
      accuracy_->use_outage_plan(*plan_, runner_->first_imu()->time_ns);
      plan_.reset();
    }
    if (accuracy_ && epoch.pose_due) {
      if (epoch.solution_deferred) {
        filter::fill_nav_solution(epoch.solution_inputs, truth_scratch_);
        accuracy_->add(truth_scratch_);
      } else {
        accuracy_->add(epoch.solution);
      }
    }
    if (epoch.pose_due) {
      const NavMode mode = epoch.solution_deferred ? epoch.solution_inputs.mode : epoch.solution.mode;
      if (mode == NavMode::kNavigation || mode == NavMode::kDeadReckoning) ++navigating_poses_;
    }
    // Last: once posted, the epoch (the writer's own slot) belongs to the writer's thread.
    if (writer_) writer_->post(epoch);
  }
  OutputEpoch* epoch_slot() override { return writer_ ? &writer_->next_slot() : nullptr; }
  // Poses written in a navigating mode (counted only when there are writers: else the runner
  // fills no solution).
  std::uint64_t navigating_poses() const { return navigating_poses_; }
  // smooth --calibration-out: the measurements the filter takes, for the calibration.
  void collect_for_calibration(CalibrationCollector* collector) { collector_ = collector; }
  void on_fused(const Measurement& m) override {
    if (collector_ != nullptr) collector_->add(m);
  }
  // Inside the timed run: the summary's rate includes writing the last epochs.
  void on_finished() override {
    if (writer_) writer_->finish();
  }

 private:
  TruthAccuracy* accuracy_;
  std::optional<GnssOutagePlan> plan_;  // until handed to accuracy_
  const FusionRunner* runner_ = nullptr;
  std::optional<PoseOutputThread> writer_;
  NavSolution truth_scratch_;  // a pose's solution for truth scoring when the writers fill theirs
  CalibrationCollector* collector_ = nullptr;
  std::uint64_t navigating_poses_ = 0;
};

struct PoseCounts {
  bool asked = false;            // a pose output was given (--fe-out, --mip-out, --csv, --lcm)
  std::uint64_t written = 0;
  std::uint64_t navigating = 0;  // of those, in navigation or dead reckoning
};

// The one-line reason a replay produced nothing useful, or "" when it did (see ReplayResult).
std::string replay_failure(const Summary& summary, std::uint64_t imu_fused, const std::vector<NavMode>& modes,
                           const PoseCounts& poses) {
  for (const InputSummary& in : summary.inputs) {
    if (std::string reason = no_frame_reason(in); !reason.empty()) return reason;
  }
  if (imu_fused == 0) {
    const KindSummary& imu = summary.kinds[static_cast<std::size_t>(MeasurementKind::kImu)];
    if (imu.decoded == 0) return "the inputs hold no IMU sample (a GNSS-only log?): nothing to navigate with";
    std::string reasons;
    for (const auto& [reason, n] : imu.rejected) reasons += (reasons.empty() ? "" : ", ") + reason + ": " + std::to_string(n);
    return "none of the " + std::to_string(imu.decoded) + " IMU samples was fused (rejected: " + reasons + ")";
  }
  const bool left_initialization = std::any_of(modes.begin(), modes.end(), [](NavMode m) {
    return m != NavMode::kInvalid && m != NavMode::kInitializing;
  });
  if (!left_initialization) {
    return "the filter never left initialization over " + std::to_string(imu_fused) +
           " IMU samples (no attitude, no navigation)";
  }
  if (poses.asked && poses.navigating == 0) {
    std::string reached;
    for (const NavMode m : modes) reached += (reached.empty() ? "" : ", ") + std::string(to_string(m));
    return "none of the " + std::to_string(poses.written) +
           " poses written is in navigation (modes reached: " + reached + "): the outputs hold no position";
  }
  return "";
}

// The accuracy table into the summary under `key`; returns it printed.
std::string report_accuracy(const TruthAccuracy& accuracy, const std::string& truth, const char* key, Summary& summary) {
  nlohmann::ordered_json a = accuracy.to_json();
  a["truth"] = truth;
  summary.extra[key] = a;
  std::ostringstream text;
  accuracy.print(text);
  return text.str();
}

// `smooth`: the recorded forward pass smoothed into the outputs and the truth comparison; what the
// smoother did goes into the summary.
void smooth_record(filter::ForwardRecorder& record, const FusionRunner& runner, const filter::FilterOptions& o,
                   double rate_hz, const std::optional<GnssOutagePlan>& outages, PoseOutputs& outputs,
                   TruthAccuracy* accuracy, CalibrationCollector* collector, ReplayResult& result) {
  record.close(runner.engine().core());
  const TimeSource time_source = runner.first_imu() ? runner.first_imu()->time_source : TimeSource::kUnknown;
  if (accuracy != nullptr && outages && runner.first_imu()) accuracy->use_outage_plan(*outages, runner.first_imu()->time_ns);
  std::function<void(const filter::SmoothedSample&)> also;
  if (collector != nullptr) also = [collector](const filter::SmoothedSample& sample) { collector->add(sample); };
  const SmoothedPassResult pass = write_smoothed(record, o, time_source, rate_hz, outputs, accuracy, also);
  const filter::SmootherStats& s = pass.stats;
  result.summary.extra["smoother"] = {{"record_mb", static_cast<double>(record.bytes()) / 1e6},
                                      {"records_replaced", record.replaced()},
                                      {"intervals", s.intervals},
                                      {"segments", s.segments},
                                      {"singular_intervals", s.singular},
                                      {"imu_samples", s.imu_samples},
                                      {"smoothed_samples", s.smoothed_samples},
                                      {"poses", pass.poses},
                                      {"wall_s", pass.wall_s}};
  std::ostringstream text;
  text << "smoother: " << s.smoothed_samples << " of " << s.imu_samples << " IMU samples smoothed over "
       << s.intervals << " covariance intervals in " << s.segments << " segment(s)";
  if (s.singular > 0) text << ", " << s.singular << " interval(s) not invertible";
  text << "; record " << static_cast<double>(record.bytes()) / 1e6 << " MB (" << record.replaced()
       << " records replaced by re-propagation); " << pass.poses << " smoothed poses in " << pass.wall_s << " s\n";
  result.smoother_text = text.str();
  result.poses = pass.poses;
  result.navigating_poses = pass.navigating_poses;
}

// --calibration-out: the calibration over the collected log, its table into the result and
// summary, the calibrated configuration to the file.
calib::CalibrationResult calibrate_log(const CalibrationCollector& collector, const config::Config& config,
                                       const std::string& path, ReplayResult& result) {
  const calib::CalibrationResult r = calibration_solver()(collector.log());
  result.summary.extra["batch_calibration"] = calibration_json(r);  // beside the filter's own "calibration"
  result.calibration_text = calibration_table(r);
  if (r.epochs == 0 || r.iterations == 0) throw CommandError("calibration failed: " + r.message);
  OutputFile out(path);
  out.write(calibration_yaml(config, r));
  out.commit();
  return r;
}

// A calibration round that moved no key by more than this changes nothing a further round could
// improve: 1 ms of time offset, 1 cm of lever arm, 0.05 deg of mounting (a fifth to a half of what
// issue 16 holds the calibration to).
bool calibration_settled(const config::Config& before, const config::Config& after) {
  auto moved = [](const std::array<double, 3>& a, const std::array<double, 3>& b, double limit) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (std::abs(a[i] - b[i]) > limit) return true;
    }
    return false;
  };
  return std::abs(after.imu.time_offset_s - before.imu.time_offset_s) <= 1e-3 &&
         !moved(before.gnss.lever_arm_m, after.gnss.lever_arm_m, 0.01) &&
         !moved(before.imu.mounting_rpy_deg, after.imu.mounting_rpy_deg, 0.05);
}

// One run over the inputs with `config`: the fusion, the smoother and the calibration when asked
// (`calibration` set to its result).
ReplayResult replay_with(const ReplayOptions& options, const std::vector<InputSpec>& specs,
                         const std::optional<Recording>& recording, const config::Config& config,
                         std::optional<calib::CalibrationResult>& calibration) {
  const double rate_hz = options.output_rate_hz.value_or(config.output.rate_hz);
  if (!(rate_hz >= 0.0)) throw CommandError("output rate must be >= 0 Hz (0 = every IMU sample)");

  // Everything that can fail on bad arguments is opened before the (long) run starts.
  std::vector<std::string> input_paths;
  for (const InputSpec& spec : specs) input_paths.push_back(spec.path);
  if (recording) {
    for (const RecordedInput& in : recording->inputs) input_paths.push_back(in.raw_path);
  }
  if (!options.truth_path.empty()) input_paths.push_back(options.truth_path);
  check_output_paths(input_paths,
                     {{"--fe-out", options.fe_out}, {"--mip-out", options.mip_out}, {"--csv", options.csv_out},
                      {"--nmea-out", options.nmea_out}, {"--innovations-csv", options.innovations_csv}});
  const MeasurementMerger::Options merge{.chunk_bytes = 16 * 1024, .allow_truncated = options.allow_truncated};
  MeasurementMerger merger = recording ? MeasurementMerger(*recording, merge) : MeasurementMerger(specs, merge);
  std::unique_ptr<TruthAccuracy> accuracy, forward_accuracy;
  if (!options.truth_path.empty()) {
    const Eigen::Vector3d lever_arm_m(config.gnss.lever_arm_m.data());
    accuracy = std::make_unique<TruthAccuracy>(options.truth_path, lever_arm_m);
    if (options.smooth) forward_accuracy = std::make_unique<TruthAccuracy>(options.truth_path, lever_arm_m);
  }
  PoseOutputs outputs;
  if (!options.fe_out.empty()) outputs.add(std::make_unique<FeFileWriter>(options.fe_out));
  if (!options.mip_out.empty()) outputs.add(std::make_unique<MipFileWriter>(options.mip_out));
  if (!options.csv_out.empty()) outputs.add(std::make_unique<CsvPoseWriter>(options.csv_out));
  if (!options.nmea_out.empty()) outputs.add(std::make_unique<NmeaFileWriter>(options.nmea_out));
  const LcmPoseWriter* lcm = nullptr;
  if (options.lcm_url) {
    auto writer = std::make_unique<LcmPoseWriter>(*options.lcm_url);
    lcm = writer.get();
    outputs.add(std::move(writer));
  }

  std::optional<GnssOutagePlan> outages;
  if (!options.gnss_outage.empty()) {
    std::string error;
    outages = GnssOutagePlan::parse(options.gnss_outage, error);
    if (!outages) throw CommandError(error);
  }
  // Smoothing: the forward pass writes nothing and is only scored; the outputs wait for the
  // smoothed solution.
  PoseOutputs no_outputs;
  ReplayObserver observer(options.smooth ? no_outputs : outputs,
                          options.smooth ? forward_accuracy.get() : accuracy.get());
  const filter::FilterOptions filter_options = filter::options_from_config(config);
  FusionRunner runner(filter_options,
                      {.output_rate_hz = rate_hz, .solutions = observer.solutions(), .gnss_outages = outages},
                      observer);
  if (outages) observer.score_outages(*outages, runner);
  std::unique_ptr<filter::ForwardRecorder> record;
  if (options.smooth) record = record_forward_pass(runner.engine());
  std::unique_ptr<CalibrationCollector> collector;
  if (!options.calibration_out.empty()) {
    if (!options.smooth) throw CommandError("--calibration-out needs `navfuse smooth`");
    if (!calibration_solver()) throw CommandError("--calibration-out: this build has no calibration solver");
    collector = std::make_unique<CalibrationCollector>(filter_options);
    observer.collect_for_calibration(collector.get());
  }
  std::unique_ptr<InnovationCsvWriter> innovations;
  if (!options.innovations_csv.empty()) {
    innovations = std::make_unique<InnovationCsvWriter>(options.innovations_csv);
    runner.engine().set_innovation_sink(&InnovationCsvWriter::sink, innovations.get());
  }
  ReplayResult result;
  result.summary = fuse_log(merger, runner, observer,
                            {.progress_bar = options.progress, .interrupt = options.interrupt});
  if (record) {
    smooth_record(*record, runner, filter_options, rate_hz, outages, outputs, accuracy.get(), collector.get(), result);
  }
  outputs.commit();
  if (innovations) innovations->commit();
  // After the smoothed outputs are in place: a log that cannot be calibrated still has them.
  if (collector) calibration = calibrate_log(*collector, config, options.calibration_out, result);

  result.imu_samples = runner.imu_samples();
  if (!options.smooth) {
    result.poses = runner.poses();
    result.navigating_poses = observer.navigating_poses();
  }
  Summary& summary = result.summary;
  summary.extra["output"] = {{"rate_hz", rate_hz}, {"poses", result.poses}};
  if (outages) {
    summary.extra["gnss_outage"] = {
        {"period_s", outages->period_s}, {"duration_s", outages->duration_s}, {"start_s", outages->start_s}};
  }
  if (lcm) summary.extra["lcm"] = {{"published", lcm->published()}, {"failures", lcm->failures()}};
  if (accuracy) result.accuracy_text = report_accuracy(*accuracy, options.truth_path, "accuracy", summary);
  if (forward_accuracy) {
    result.forward_accuracy_text = report_accuracy(*forward_accuracy, options.truth_path, "forward_accuracy", summary);
  }
  result.truncated_inputs = merger.truncated_inputs();
  result.failure = replay_failure(summary, result.imu_samples, runner.engine().modes_reached(),
                                  {.asked = !outputs.empty(), .written = result.poses, .navigating = result.navigating_poses});
  if (!result.failure.empty()) summary.extra["failure"] = result.failure;
  const auto& imu_rejected = summary.kind(MeasurementKind::kImu).rejected;
  if (const auto it = imu_rejected.find("time_backwards"); it != imu_rejected.end()) {
    result.imu_time_backwards = it->second;
  }
  return result;
}

}  // namespace

config::Config replay_config(const std::string& config_path, std::string_view first_format) {
  if (config_path.empty()) return config::defaults_for(profile_for_format(first_format));
  try {
    return config::load_from_file(config_path);
  } catch (const config::ConfigError& e) {
    throw CommandError(e.what());
  }
}

ReplayResult run_replay(const ReplayOptions& options) {
  const bool recorded = !options.recording_dir.empty();
  if (recorded && !options.inputs.empty()) throw CommandError("replay: give INPUT files or --recording DIR, not both");
  if (!recorded && options.inputs.empty()) throw CommandError("replay needs at least one INPUT (or --recording DIR)");
  std::optional<Recording> recording;
  std::vector<InputSpec> specs;
  if (recorded) {
    recording = read_recording(options.recording_dir);
  } else {
    specs = resolve_inputs(options.inputs, options.gps_week);
  }
  config::Config config =
      recorded ? replay_config(options.config_path.empty() ? recording->config_path : options.config_path, "")
               : replay_config(options.config_path, specs.front().frontend->format);
  if (options.calibration_rounds < 1) throw CommandError("--calibration-rounds must be at least 1");
  std::optional<calib::CalibrationResult> calibration;
  ReplayResult result = replay_with(options, specs, recording, config, calibration);
  int rounds = calibration ? 1 : 0;
  while (calibration && rounds < options.calibration_rounds) {
    const config::Config next = calibrated_config(config, *calibration);
    if (calibration_settled(config, next)) break;
    config = next;
    result = replay_with(options, specs, recording, config, calibration);
    ++rounds;
  }
  if (calibration) {
    result.calibration_rounds = rounds;
    result.summary.extra["batch_calibration"]["rounds"] = rounds;
    result.calibration_text += rounds == 1 ? std::string("  1 round of smoothing and calibration\n")
                                           : "  " + std::to_string(rounds) +
                                                 " rounds of smoothing and calibration, each after the first with the "
                                                 "previous round's calibrated installation\n";
  }
  return result;
}

}  // namespace navfuse::apps

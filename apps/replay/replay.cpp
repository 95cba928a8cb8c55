#include "apps/replay/replay.hpp"

#include <memory>
#include <optional>
#include <sstream>

#include "apps/common/command_error.hpp"
#include "apps/common/input_spec.hpp"
#include "apps/lcm/lcm_pose_writer.hpp"
#include "apps/output/csv_pose_writer.hpp"
#include "apps/output/fe_pose_writer.hpp"
#include "apps/output/mip_pose_writer.hpp"
#include "apps/output/output_rate.hpp"
#include "apps/output/pose_output_thread.hpp"
#include "apps/output/pose_outputs.hpp"
#include "apps/replay/fusion_pipeline.hpp"
#include "apps/replay/measurement_merger.hpp"
#include "apps/replay/truth_accuracy.hpp"
#include "filter/engine.hpp"

namespace navfuse::apps {
namespace {

config::DeviceProfile profile_for_format(std::string_view format) {
  if (format == "vn") return config::DeviceProfile::kVn300;
  if (format == "mip") return config::DeviceProfile::kCv7;
  if (format == "unicore") return config::DeviceProfile::kUm220;
  if (format == "fe") return config::DeviceProfile::kFusionEngine;
  return config::DeviceProfile::kGeneric;
}

// Replay's use of the stream: every solution to the writers (IMU output), and at the output
// rate a pose (FusionEngine / MIP / CSV) and a truth comparison. The writers run on their own
// thread (PoseOutputThread); the truth comparison is cheap and stays here.
class ReplayObserver final : public PipelineObserver {
 public:
  ReplayObserver(PoseOutputs& outputs, TruthAccuracy* accuracy, double rate_hz)
      : accuracy_(accuracy), rate_(rate_hz) {
    if (!outputs.empty()) writer_.emplace(outputs);
  }
  void on_fused(const Measurement& m) override {
    if (kind_of(m) == MeasurementKind::kGnssPosition) num_sats_ = std::get<GnssPosition>(m).num_sats;
  }
  void on_imu_epoch(const filter::Engine& engine) override {
    if (!writer_ && accuracy_ == nullptr) return;
    const NavSolution& s = engine.solution();
    const bool pose_due = rate_.due(s.header.time_ns);
    if (writer_) writer_->post(s, pose_due, engine.stats().of(MeasurementKind::kGnssPosition).used, num_sats_);
    if (!pose_due) return;
    ++poses;
    if (accuracy_) accuracy_->add(s);
  }
  // Inside the timed run: the summary's rate includes writing the last epochs.
  void on_finished() override {
    if (writer_) writer_->finish();
  }
  std::uint64_t poses = 0;

 private:
  TruthAccuracy* accuracy_;
  OutputRate rate_;
  std::optional<PoseOutputThread> writer_;
  std::uint8_t num_sats_ = 0;
};

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
  if (options.inputs.empty()) throw CommandError("replay needs at least one INPUT");
  const std::vector<InputSpec> specs = resolve_inputs(options.inputs, options.gps_week);
  const config::Config config = replay_config(options.config_path, specs.front().frontend->format);
  const double rate_hz = options.output_rate_hz.value_or(config.output.rate_hz);
  if (!(rate_hz >= 0.0)) throw CommandError("output rate must be >= 0 Hz (0 = every IMU sample)");

  // Everything that can fail on bad arguments is opened before the (long) run starts.
  MeasurementMerger merger(specs, {.chunk_bytes = 16 * 1024, .allow_truncated = options.allow_truncated});
  std::unique_ptr<TruthAccuracy> accuracy;
  if (!options.truth_path.empty()) {
    accuracy = std::make_unique<TruthAccuracy>(options.truth_path, Eigen::Vector3d(config.gnss.lever_arm_m.data()));
  }
  PoseOutputs outputs;
  if (!options.fe_out.empty()) outputs.add(std::make_unique<FePoseWriter>(options.fe_out));
  if (!options.mip_out.empty()) outputs.add(std::make_unique<MipPoseWriter>(options.mip_out));
  if (!options.csv_out.empty()) outputs.add(std::make_unique<CsvPoseWriter>(options.csv_out));
  const LcmPoseWriter* lcm = nullptr;
  if (options.lcm_url) {
    auto writer = std::make_unique<LcmPoseWriter>(*options.lcm_url);
    lcm = writer.get();
    outputs.add(std::move(writer));
  }

  filter::Engine engine(filter::options_from_config(config));
  ReplayObserver observer(outputs, accuracy.get(), rate_hz);
  PipelineResult run = run_fusion_pipeline(merger, engine, {.progress_bar = options.progress}, observer);
  outputs.commit();

  ReplayResult result;
  result.imu_samples = run.imu_samples;
  result.poses = observer.poses;
  result.summary = std::move(run.summary);
  Summary& summary = result.summary;
  summary.extra["output"] = {{"rate_hz", rate_hz}, {"poses", result.poses}};
  if (lcm) summary.extra["lcm"] = {{"published", lcm->published()}, {"failures", lcm->failures()}};
  if (accuracy) {
    nlohmann::ordered_json a = accuracy->to_json();
    a["truth"] = options.truth_path;
    summary.extra["accuracy"] = a;
    std::ostringstream text;
    accuracy->print(text);
    result.accuracy_text = text.str();
  }
  result.truncated_inputs = merger.truncated_inputs();
  return result;
}

}  // namespace navfuse::apps

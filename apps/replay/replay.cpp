#include "apps/replay/replay.hpp"

#include <chrono>
#include <memory>
#include <sstream>

#include "apps/common/command_error.hpp"
#include "apps/common/input_spec.hpp"
#include "apps/output/csv_pose_writer.hpp"
#include "apps/output/fe_pose_writer.hpp"
#include "apps/output/mip_pose_writer.hpp"
#include "apps/output/output_rate.hpp"
#include "apps/output/pose_outputs.hpp"
#include "apps/replay/measurement_merger.hpp"
#include "apps/replay/progress_bar.hpp"
#include "apps/replay/time_base_gate.hpp"
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

// Used / rejected-by-reason of the filter, plus the app's own time-base rejections.
void fill_measurement_counts(const filter::FilterStats& stats, const MeasurementMerger& merger,
                             const std::array<std::map<std::string, std::uint64_t>,
                                              static_cast<std::size_t>(MeasurementKind::kCount)>& gated,
                             Summary& summary) {
  for (std::size_t k = 0; k < summary.kinds.size(); ++k) {
    KindSummary& ks = summary.kinds[k];
    const filter::KindStats& fs = stats.kinds[k];
    ks.decoded = merger.decoded()[k];
    ks.used = fs.used;
    for (std::size_t r = 0; r < fs.rejected.size(); ++r) {
      if (fs.rejected[r] > 0) ks.rejected[std::string(filter::to_string(static_cast<filter::RejectReason>(r)))] += fs.rejected[r];
    }
    // A kind the filter does not fuse (device solutions, magnetometer...): "ignored".
    if (fs.ignored > 0) ks.rejected["ignored"] += fs.ignored;
    for (const auto& [reason, n] : gated[k]) ks.rejected[reason] += n;
  }
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
  if (options.inputs.empty()) throw CommandError("replay needs at least one INPUT");
  std::vector<InputSpec> specs;
  for (const auto& arg : options.inputs) specs.push_back(resolve_input(arg));
  const config::Config config = replay_config(options.config_path, specs.front().frontend->format);
  const double rate_hz = options.output_rate_hz.value_or(config.output.rate_hz);
  if (!(rate_hz >= 0.0)) throw CommandError("output rate must be >= 0 Hz (0 = every IMU sample)");

  // Everything that can fail on bad arguments is opened before the (long) run starts.
  MeasurementMerger merger(specs, {.chunk_bytes = 16 * 1024, .allow_truncated = options.allow_truncated});
  std::unique_ptr<TruthAccuracy> accuracy;
  if (!options.truth_path.empty()) accuracy = std::make_unique<TruthAccuracy>(options.truth_path);
  PoseOutputs outputs;
  if (!options.fe_out.empty()) outputs.add(std::make_unique<FePoseWriter>(options.fe_out));
  if (!options.mip_out.empty()) outputs.add(std::make_unique<MipPoseWriter>(options.mip_out));
  if (!options.csv_out.empty()) outputs.add(std::make_unique<CsvPoseWriter>(options.csv_out));
  const bool need_solution = !outputs.empty() || accuracy != nullptr;

  filter::Engine engine(filter::options_from_config(config));
  TimeBaseGate gate;
  OutputRate rate(rate_hz);
  ProgressBar progress(merger.total_bytes(), options.progress);
  std::array<std::map<std::string, std::uint64_t>, static_cast<std::size_t>(MeasurementKind::kCount)> gated;

  ReplayResult result;
  std::uint64_t epoch = engine.imu_epoch();
  std::uint8_t num_sats = 0;
  std::uint64_t processed = 0;
  Measurement m;
  const auto start = std::chrono::steady_clock::now();
  while (merger.next(m)) {
    const MeasurementKind kind = kind_of(m);
    if (const auto reason = gate.check(m)) {
      ++gated[static_cast<std::size_t>(kind)][std::string(*reason)];
      continue;
    }
    if (kind == MeasurementKind::kGnssPosition) num_sats = std::get<GnssPosition>(m).num_sats;
    engine.process(m);
    if (kind == MeasurementKind::kImu) {
      ++result.imu_samples;
      if (engine.imu_epoch() != epoch && need_solution) {
        epoch = engine.imu_epoch();
        const NavSolution& s = engine.solution();
        outputs.on_imu(s);
        if (rate.due(s.header.time_ns)) {
          ++result.poses;
          outputs.on_pose(s, engine.stats().of(MeasurementKind::kGnssPosition).used, num_sats);
          if (accuracy) accuracy->add(s);
        }
      }
    }
    if ((++processed & 0x3FFF) == 0) progress.update(merger.bytes_read());
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.clear();
  outputs.commit();

  Summary& summary = result.summary;
  summary.inputs = merger.input_summaries();
  fill_measurement_counts(engine.stats(), merger, gated, summary);
  RunStats run;
  run.wall_s = wall_s;
  run.imu_samples_per_s = wall_s > 0.0 ? static_cast<double>(result.imu_samples) / wall_s : 0.0;
  for (NavMode mode : engine.modes_reached()) run.modes_reached.emplace_back(to_string(mode));
  summary.run = run;
  summary.extra["output"] = {{"rate_hz", rate_hz}, {"poses", result.poses}};
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

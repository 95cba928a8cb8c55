#include "apps/bench/bench_log.hpp"

#include <memory>
#include <stdexcept>

#include "apps/common/command_error.hpp"
#include "apps/common/empty_run.hpp"
#include "apps/common/input_spec.hpp"
#include "apps/fusion/fusion_runner.hpp"
#include "apps/fusion/log_fusion.hpp"
#include "apps/fusion/measurement_merger.hpp"
#include "apps/replay/replay.hpp"
#include "apps/replay/smoothed_pass.hpp"
#include "apps/output/output_rate.hpp"
#include "filter/engine.hpp"
#include "filter/smoother/forward_record.hpp"
#include "filter/smoother/rts_smoother.hpp"

namespace navfuse::apps::bench {
namespace {

bool is_fix(const GnssPosition& p) {
  return (p.header.valid & GnssPosition::kValidPosition) != 0 && p.fix >= GnssFixType::kFix2D &&
         p.fix != GnssFixType::kDeadReckoning;
}

// Same clock: GPS time for both, or one device's own clock on the same input stream.
bool same_time_base(const MeasurementHeader& a, const MeasurementHeader& b) {
  return a.time_source == b.time_source && (a.time_source == TimeSource::kGps || a.stream_id == b.stream_id);
}

std::string input_name(const std::vector<InputSpec>& specs, std::size_t i) {
  return i < specs.size() ? "'" + specs[i].path + "'" : "input " + std::to_string(i);
}

// Bench's use of the stream: the device's own solution (from whichever clock, checked after the
// run), the GNSS fix times, and navfuse's poses at the output rate, exactly as replay writes them.
class BenchObserver final : public FusionObserver {
 public:
  BenchObserver(BenchLog& log, const std::vector<InputSpec>& specs) : log_(log), specs_(specs) {}
  void on_offered(const Measurement& m) override {
    if (kind_of(m) != MeasurementKind::kDeviceSolution) return;
    const MeasurementHeader& header = header_of(m);
    if (!device_header) {
      device_header = header;
      log_.device_input = header.stream_id;
      log_.device_format = std::string(specs_[header.stream_id].frontend->format);
    }
    if (header.stream_id == device_header->stream_id) {
      log_.device.append(track_sample_from(std::get<NavSolution>(m)));
    } else {
      ++log_.other_device_solutions;
    }
  }
  void on_fused(const Measurement& m) override {
    if (kind_of(m) == MeasurementKind::kGnssPosition && is_fix(std::get<GnssPosition>(m))) {
      log_.gnss_fix_times_ns.add(header_of(m).time_ns);
    }
  }
  void on_epoch(const OutputEpoch& epoch, const filter::Engine&) override {
    if (epoch.pose_due) log_.navfuse.append(track_sample_from(epoch.solution));
  }
  std::optional<MeasurementHeader> device_header;

 private:
  BenchLog& log_;
  const std::vector<InputSpec>& specs_;
};

// The recorded run smoothed, at the same pose times as navfuse's forward poses (OutputRate).
void smooth_into(filter::ForwardRecorder& record, const FusionRunner& runner, const filter::FilterOptions& o,
                 double rate_hz, SolutionTrack& out) {
  record.close(runner.engine().core());
  const TimeSource time_source = runner.first_imu() ? runner.first_imu()->time_source : TimeSource::kUnknown;
  OutputRate rate(rate_hz);
  const filter::SmootherStats stats = filter::smooth(record, [&](const filter::SmoothedSample& s) {
    if (rate.due(s.x.time_ns)) out.append(track_sample_from(filter::smoothed_solution(s, o, time_source)));
  });
  if (!stats.error.empty()) throw CommandError("smoothing failed: " + stats.error);
}

}  // namespace

BenchLog collect_bench_log(const BenchLogOptions& options) {
  if (options.inputs.empty()) throw CommandError("bench needs at least one INPUT");
  const std::vector<InputSpec> specs = resolve_inputs(options.inputs, options.gps_week);
  const config::Config config = replay_config(options.config_path, specs.front().frontend->format);

  MeasurementMerger merger(specs, {.chunk_bytes = 16 * 1024, .allow_truncated = options.allow_truncated});
  BenchLog log;
  log.output_rate_hz = config.output.rate_hz;
  log.antenna_lever_arm_m = Eigen::Vector3d(config.gnss.lever_arm_m.data());
  BenchObserver observer(log, specs);
  const filter::FilterOptions filter_options = filter::options_from_config(config);
  FusionRunner runner(filter_options,
                      {.output_rate_hz = config.output.rate_hz, .solutions = FusionRunner::Solutions::kPoses, .gnss_outages = {}},
                      observer);
  std::unique_ptr<filter::ForwardRecorder> record;
  if (options.smooth) record = record_forward_pass(runner.engine());
  log.summary = fuse_log(merger, runner, observer,
                         {.progress_bar = options.progress,
                          .progress_lines_label = options.progress ? "navfuse bench" : nullptr,
                          .interrupt = options.interrupt});
  if (record) smooth_into(*record, runner, filter_options, config.output.rate_hz, log.smoothed);
  const std::optional<MeasurementHeader>& imu_header = runner.first_imu();
  const std::optional<MeasurementHeader>& device_header = observer.device_header;
  if (imu_header) {
    log.start_ns = imu_header->time_ns;
    log.end_ns = runner.last_imu_ns();
  }
  log.imu_samples = runner.imu_samples();

  for (const InputSummary& in : log.summary.inputs) {
    if (std::string reason = no_frame_reason(in); !reason.empty()) throw nothing_useful_error("bench", reason);
  }
  if (!imu_header) {
    std::string names;
    for (std::size_t i = 0; i < specs.size(); ++i) names += (i ? ", " : "") + input_name(specs, i);
    throw nothing_useful_error("bench", "no IMU samples in " + names +
                                            ": bench runs navfuse on the log's own IMU data (log the device's IMU "
                                            "output too)");
  }
  log.time_source = imu_header->time_source;
  if (device_header && !same_time_base(*device_header, *imu_header)) {
    throw CommandError("mismatched time bases: the device solution in " + input_name(specs, device_header->stream_id) +
                       " is timed by " + std::string(to_string(device_header->time_source)) + " but the IMU in " +
                       input_name(specs, imu_header->stream_id) + " by " +
                       std::string(to_string(imu_header->time_source)) + "; the two cannot be aligned");
  }
  return log;
}

}  // namespace navfuse::apps::bench

#include "apps/bench/bench_log.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <unistd.h>

#include "apps/common/command_error.hpp"
#include "apps/common/input_spec.hpp"
#include "apps/output/output_rate.hpp"
#include "apps/replay/measurement_merger.hpp"
#include "apps/replay/progress_bar.hpp"
#include "apps/replay/replay.hpp"
#include "apps/replay/time_base_gate.hpp"
#include "filter/engine.hpp"

namespace navfuse::apps::bench {
namespace {

// Progress of a long log when stderr is not a terminal (CI logs, pipes): a line every 10 %,
// where the terminal gets replay's redrawn bar instead.
class ProgressLines {
 public:
  ProgressLines(std::uint64_t total_bytes, bool enabled)
      : total_(total_bytes), enabled_(enabled && total_bytes >= ProgressBar::kMinBytes && isatty(2) == 0) {}
  void update(std::uint64_t done) {
    if (!enabled_) return;
    const int tenth = static_cast<int>(10 * done / total_);
    if (tenth <= shown_) return;
    shown_ = tenth;
    std::fprintf(stderr, "navfuse bench: %d %% of %.0f MB processed\n", 10 * tenth, static_cast<double>(total_) / 1e6);
  }

 private:
  std::uint64_t total_;
  bool enabled_;
  int shown_ = 0;
};

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

}  // namespace

BenchLog collect_bench_log(const BenchLogOptions& options) {
  if (options.inputs.empty()) throw CommandError("bench needs at least one INPUT");
  std::vector<InputSpec> specs;
  for (const auto& arg : options.inputs) specs.push_back(resolve_input(arg));
  const config::Config config = replay_config(options.config_path, specs.front().frontend->format);

  MeasurementMerger merger(specs, {.chunk_bytes = 16 * 1024, .allow_truncated = options.allow_truncated});
  filter::Engine engine(filter::options_from_config(config));
  TimeBaseGate gate;
  OutputRate rate(config.output.rate_hz);
  ProgressBar bar(merger.total_bytes(), options.progress);
  ProgressLines lines(merger.total_bytes(), options.progress);

  BenchLog log;
  log.output_rate_hz = config.output.rate_hz;
  std::optional<MeasurementHeader> imu_header, device_header;
  std::uint64_t epoch = engine.imu_epoch();
  std::uint64_t processed = 0;
  const auto start = std::chrono::steady_clock::now();
  Measurement m;
  while (merger.next(m)) {
    const MeasurementKind kind = kind_of(m);
    const MeasurementHeader& header = header_of(m);
    if (kind == MeasurementKind::kDeviceSolution) {
      // Kept whatever the gate says: the device's solution is the other half of the benchmark.
      if (!device_header) {
        device_header = header;
        log.device_input = header.stream_id;
        log.device_format = std::string(specs[header.stream_id].frontend->format);
      }
      if (header.stream_id == device_header->stream_id) {
        log.device.append(track_sample_from(std::get<NavSolution>(m)));
      } else {
        ++log.other_device_solutions;
      }
    }
    if (gate.check(m)) continue;  // on another clock than the IMU: replay does not fuse it either
    if (kind == MeasurementKind::kGnssPosition && is_fix(std::get<GnssPosition>(m))) {
      log.gnss_fix_times_ns.push_back(header.time_ns);
    }
    engine.process(m);
    if (kind == MeasurementKind::kImu) {
      if (!imu_header) {
        imu_header = header;
        log.start_ns = header.time_ns;
      }
      log.end_ns = std::max(log.end_ns, header.time_ns);
      ++log.imu_samples;
      if (engine.imu_epoch() != epoch) {
        epoch = engine.imu_epoch();
        const NavSolution& s = engine.solution();
        if (rate.due(s.header.time_ns)) log.navfuse.append(track_sample_from(s));
      }
    }
    if ((++processed & 0x3FFF) == 0) {
      bar.update(merger.bytes_read());
      lines.update(merger.bytes_read());
    }
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bar.clear();

  if (!imu_header) {
    std::string names;
    for (std::size_t i = 0; i < specs.size(); ++i) names += (i ? ", " : "") + input_name(specs, i);
    throw CommandError("no IMU samples in " + names +
                       ": bench runs navfuse on the log's own IMU data (log the device's IMU output too)");
  }
  log.time_source = imu_header->time_source;
  if (device_header && !same_time_base(*device_header, *imu_header)) {
    throw CommandError("mismatched time bases: the device solution in " + input_name(specs, device_header->stream_id) +
                       " is timed by " + std::string(to_string(device_header->time_source)) + " but the IMU in " +
                       input_name(specs, imu_header->stream_id) + " by " +
                       std::string(to_string(imu_header->time_source)) + "; the two cannot be aligned");
  }
  std::sort(log.gnss_fix_times_ns.begin(), log.gnss_fix_times_ns.end());

  log.summary.inputs = merger.input_summaries();
  for (std::size_t k = 0; k < log.summary.kinds.size(); ++k) {
    log.summary.kinds[k].decoded = merger.decoded()[k];
    log.summary.kinds[k].used = engine.stats().kinds[k].used;
  }
  RunStats run;
  run.wall_s = wall_s;
  run.imu_samples_per_s = wall_s > 0.0 ? static_cast<double>(log.imu_samples) / wall_s : 0.0;
  for (NavMode mode : engine.modes_reached()) run.modes_reached.emplace_back(to_string(mode));
  log.summary.run = run;
  return log;
}

}  // namespace navfuse::apps::bench

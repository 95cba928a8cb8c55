// What `navfuse bench` takes from a log: it runs the log's sensor data through the filter exactly
// as `navfuse replay` does (same input merge, time-base gate, configuration and pose output
// rate, so the poses are the ones replay writes), and keeps, alongside navfuse's poses, the
// device's own solution from the same log and the times of its GNSS fixes. All of them are kept
// on disk as they come (solution_track.hpp), so collecting a long log takes no more memory than
// replaying it.
//
// The device solution is taken from one input: the first that carries one (a second device's
// solutions are counted and left out). It must be on the IMU's time base, or the two cannot be
// aligned: GPS time for both, or the same device's own clock.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "apps/bench/solution_track.hpp"
#include "apps/common/external_sort.hpp"
#include "apps/common/summary.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::apps::bench {

struct BenchLogOptions {
  std::vector<std::string> inputs;  // [FORMAT:]PATH
  std::optional<std::int32_t> gps_week;  // --gps-week: the week of imutxt inputs
  std::string config_path;          // empty: the device profile of the first input
  bool allow_truncated = false;
  bool progress = false;  // report progress of long logs on stderr
  bool smooth = false;    // --reference smoothed: record the run and smooth it (BenchLog::smoothed)
  // Polled while fusing (InterruptSignals::received()): non-zero stops reading; the log is what
  // was read so far and summary.interrupted_by says so.
  const std::atomic<int>* interrupt = nullptr;
};

struct BenchLog {
  SolutionTrack navfuse;  // navfuse's poses at output.rate_hz, every mode
  SolutionTrack device;   // the device's own solutions, every mode
  SolutionTrack smoothed;  // --reference smoothed: navfuse's run smoothed (RTS), at the pose times
  std::optional<std::size_t> device_input;  // index into `inputs` of the device's stream
  std::string device_format;                // "vn", "mip", "unicore", "fe"
  std::uint64_t other_device_solutions = 0;  // from a second input, not compared
  ExternalSort<std::int64_t> gnss_fix_times_ns;  // read back sorted
  std::int64_t start_ns = 0;                     // first IMU sample
  std::int64_t end_ns = 0;                       // last IMU sample
  TimeSource time_source = TimeSource::kUnknown;  // the IMU's (and so navfuse's) time base
  std::uint64_t imu_samples = 0;
  double output_rate_hz = 0.0;
  Eigen::Vector3d antenna_lever_arm_m = Eigen::Vector3d::Zero();  // gnss.lever_arm_m of the config
  Summary summary;  // inputs and decoded counts, as replay reports them
};

// Throws CommandError with a one-line reason: unreadable input, bad config, a device solution on
// another time base than the IMU; exit 2 (nothing_useful_error) for an input without a frame or
// a log without IMU samples.
BenchLog collect_bench_log(const BenchLogOptions& options);

}  // namespace navfuse::apps::bench

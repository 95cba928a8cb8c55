// `navfuse replay`: logs in, filter, pose outputs and a summary out, as fast as the machine
// allows. The command line (replay_command.hpp) is a thin layer over run_replay(), which tests
// and benchmarks call in-process.
//
// Flow: inputs are resolved ([FORMAT:]PATH, format detected from the bytes otherwise), decoded
// a chunk at a time and merged by measurement time (MeasurementMerger); measurements on another
// clock than the IMU's are rejected as "time_base" (TimeBaseGate); everything else goes to
// filter::Engine. After every IMU sample the solution goes to the writers; at output.rate_hz
// (0 = every IMU sample) it is also a pose: written as FusionEngine / MIP / CSV and compared with
// truth when given. Output files appear only complete (OutputFile); a failure leaves none.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "apps/common/summary.hpp"
#include "core/config/config.hpp"

namespace navfuse::apps {

struct ReplayOptions {
  std::string config_path;  // empty: defaults of the device profile matching the first input
  std::vector<std::string> inputs;
  // --recording DIR: the inputs of a `navfuse run --record DIR`, in the live run's order, with
  // the run's config unless config_path is given (instead of `inputs`).
  std::string recording_dir;
  std::optional<std::int32_t> gps_week;  // --gps-week: the week of imutxt inputs
  std::string fe_out, mip_out, csv_out, nmea_out;
  std::string innovations_csv;  // --innovations-csv
  std::string truth_path;
  std::optional<std::string> lcm_url;  // --lcm [URL]: NAVFUSE_POSE / NAVFUSE_IMU at the pose rate ("" = LCM's default)
  std::optional<double> output_rate_hz;  // overrides the config's output.rate_hz
  std::string gnss_outage;  // --gnss-outage PERIOD_S:DURATION_S[:START_S] (empty: none)
  // `navfuse smooth`: the fusion run is recorded and smoothed (RTS, filter/smoother/); the outputs
  // and the truth comparison get the smoothed solution, the forward one is scored beside it.
  bool smooth = false;
  // smooth --calibration-out FILE: the batch calibration (calibration/, through the solver the
  // executable registers, calibration_hook.hpp) over the log from the smoothed solution, written
  // as a config with the calibrated keys (calibration_output.hpp).
  std::string calibration_out;
  // Rounds of smoothing and calibration, each run with the previous round's calibrated
  // installation: the smoothed trajectory the calibration starts from is only as good as the
  // configuration it was made with (a 125 ms IMU offset left out of it costs the heading degrees,
  // and one round then stops 26 ms short; a second round found it to 2 ms, parking_drive). Stops
  // early once a round moves nothing by more than kCalibrationSettled (replay.cpp).
  int calibration_rounds = 2;
  bool allow_truncated = false;
  bool progress = false;  // progress bar on stderr (only drawn when it is a terminal)
  // Polled while replaying (InterruptSignals::received()): non-zero stops early; the outputs are
  // committed with what was processed and ReplayResult::summary.interrupted_by says so.
  const std::atomic<int>* interrupt = nullptr;
};

struct ReplayResult {
  Summary summary;
  std::uint64_t imu_samples = 0;  // IMU samples given to the filter
  std::uint64_t poses = 0;        // pose epochs written
  std::uint64_t navigating_poses = 0;  // of those, in navigation, dead reckoning or smoothed
  std::vector<std::string> truncated_inputs;
  std::string accuracy_text;      // printable accuracy table (with --truth)
  std::string forward_accuracy_text;  // smooth: the forward filter's table beside it
  std::string smoother_text;          // smooth: what the smoother did, one paragraph
  std::string calibration_text;       // smooth --calibration-out: the calibration table
  int calibration_rounds = 0;         // smooth --calibration-out: rounds run
  // Why the run produced nothing useful, one line (empty: it did): no IMU sample fused (an input
  // with no frame decoded, a log without IMU, every sample rejected), or the filter never left
  // initialization. `navfuse replay` exits 2 with it, after the summary.
  std::string failure;
  // IMU samples rejected because their time went back (a log concatenated with itself, a clock
  // reset): the filter skipped them, so the outputs miss that part. Warned about on stderr.
  std::uint64_t imu_time_backwards = 0;
};

// Throws CommandError with a one-line reason on bad input or config.
ReplayResult run_replay(const ReplayOptions& options);

// The configuration for a replay: the file when given (errors name the key), else the defaults
// of the device profile that matches the format ("vn" -> vn300, "mip" -> cv7, ...).
config::Config replay_config(const std::string& config_path, std::string_view first_format);

}  // namespace navfuse::apps

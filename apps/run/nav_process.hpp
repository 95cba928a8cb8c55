// The companion-computer nav process behind `navfuse run` (DESIGN.md use 1). Threads:
//
//   input readers (one per --in) --measurements--> [bounded queue] --> filter thread
//   LCM thread (NAVFUSE_AID_*)   --aiding-------->        ^               |
//   output threads (MIP 0x13)    --aiding-------->--------'               |
//   output threads (FE/MIP commands) --engine actions--> filter thread    |
//   filter thread --epochs--> output threads (--fe-out, --mip-out, each its own link)
//   filter thread --epochs, GNSS, status--> LCM thread (NAVFUSE_POSE/IMU/GNSS/STATUS)
//   filter thread --latest position--> corrections thread (GGA to the caster) --RTCM--> an input
//
// Only the filter thread touches the engine. Every arrow into a consumer that may be slow is a
// bounded queue that drops (and counts) rather than waits, so nothing downstream can stall the
// filter, and nothing is allocated per IMU sample on the way through.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

#include "apps/common/summary.hpp"
#include "apps/fusion/fusion_runner.hpp"
#include "apps/output/pose_output_thread.hpp"
#include "apps/output/pose_outputs.hpp"
#include "apps/run/arrived_measurement.hpp"
#include "apps/run/corrections_forwarder.hpp"
#include "apps/run/engine_action.hpp"
#include "apps/run/input_reader.hpp"
#include "apps/run/latency_tracker.hpp"
#include "apps/run/lcm_service.hpp"
#include "apps/run/output_sink.hpp"
#include "apps/run/rover_position.hpp"
#include "apps/run/run_options.hpp"
#include "apps/run/status_reporter.hpp"
#include "core/config/config.hpp"
#include "filter/engine.hpp"

namespace navfuse::apps {

class NavProcess final : private FusionObserver {
 public:
  // Loads the configuration and opens every input, output and LCM, so that any bad argument
  // (unknown format, bad URI, missing file or device, bad config key) is a one-line
  // CommandError before a thread starts.
  explicit NavProcess(const RunOptions& options);
  ~NavProcess();
  NavProcess(const NavProcess&) = delete;
  NavProcess& operator=(const NavProcess&) = delete;

  void start();
  // True once every input has ended (files read to the end) and the filter has used it all.
  bool finished() const { return finished_.load(std::memory_order_acquire); }
  // Orderly shutdown: inputs stop, the filter fuses what is queued, outputs and LCM flush.
  void stop();
  // Inputs, measurements decoded / used / rejected and run statistics (complete after stop()).
  Summary summary() const;
  // --configure-device: the first input whose device refused its set-up or did not read back a
  // setting as written, with the error; "" while none has.
  std::string setup_error() const;
  // After stop(): the write error of each file output that lost bytes (OutputSink::write_error).
  std::vector<std::string> output_errors() const;

 private:
  void filter_loop();
  // FusionObserver: the runner's fused measurements and epochs go to the outputs and LCM.
  void on_fused(const Measurement& m) override;
  void on_epoch(const OutputEpoch& epoch, const filter::Engine& engine) override;
  void track_gnss(const Measurement& m);
  void apply_actions();
  void report_status();
  bool inputs_ended() const;

  RunOptions options_;
  config::Config config_;
  std::unique_ptr<FusionRunner> runner_;  // the filter thread's only way to the engine
  MeasurementQueue queue_;
  EngineActionQueue actions_;
  LatencyTracker latency_;
  std::unique_ptr<RunRecorder> recorder_;
  std::unique_ptr<RealtimePacer> pacer_;
  std::vector<std::unique_ptr<InputReader>> inputs_;
  std::vector<std::unique_ptr<OutputSink>> outputs_;
  std::unique_ptr<LcmService> lcm_;
  // Declared before the forwarder whose thread reads it: destroyed after it.
  std::unique_ptr<RoverPosition> rover_;  // for the caster's GGA uploads (--corrections ...?gga=S)
  std::unique_ptr<CorrectionsForwarder> corrections_;
  // File outputs (--csv): written on a thread of their own, as in replay; a file never drops an
  // epoch, so this thread holds the filter back if the disk cannot keep up.
  PoseOutputs files_;
  std::unique_ptr<PoseOutputThread> file_thread_;
  bool file_failed_ = false;  // a write failed: the files are abandoned (filter thread only)

  // Filter thread state.
  StatusReporter status_;
  ArrivedMeasurement item_;
  std::vector<InputSnapshot> snapshots_;
  GnssPosition pending_fix_;  // waiting for the velocity of the same epoch (NAVFUSE_GNSS)
  bool fix_pending_ = false;
  std::int64_t next_status_ns_ = 0;
  std::int64_t started_ns_ = 0;
  std::int64_t stopped_ns_ = 0;

  std::thread filter_thread_;
  std::atomic<bool> stop_filter_{false};
  std::atomic<bool> finished_{false};
  bool stopped_ = false;
};

}  // namespace navfuse::apps

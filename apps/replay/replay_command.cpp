#include "apps/replay/replay_command.hpp"

#include <iostream>
#include <memory>

#include "apps/common/command_error.hpp"
#include "apps/common/command_help.hpp"
#include "apps/common/empty_run.hpp"
#include "apps/common/interrupt_signals.hpp"
#include "apps/common/gps_week_option.hpp"
#include "apps/common/summary.hpp"
#include "apps/replay/replay.hpp"

namespace navfuse::apps {
namespace {

struct ReplayArgs {
  ReplayOptions options;
  std::string summary_json;
  double rate_hz = -1.0;
  std::string lcm_url;
  CLI::Option* lcm = nullptr;
  bool quiet = false;
  bool allow_empty = false;
};

int run(ReplayArgs& args) {
  if (args.rate_hz >= 0.0) args.options.output_rate_hz = args.rate_hz;
  if (args.lcm->count() > 0) {
    // --lcm takes an optional value, so `--lcm LOG` would read the log as the URL.
    check_lcm_url(args.lcm_url);
    args.options.lcm_url = args.lcm_url;
  }
  args.options.progress = !args.quiet;
  const InterruptSignals signals;
  args.options.interrupt = &InterruptSignals::received();
  const ReplayResult result = run_replay(args.options);
  if (!args.summary_json.empty()) write_json_file(args.summary_json, result.summary.to_json(/*decode_only=*/false));
  for (const auto& path : result.truncated_inputs) {
    std::cerr << "navfuse: warning: '" << path << "' ends with an incomplete frame (replayed up to it)\n";
  }
  if (!args.quiet) {
    result.summary.print(std::cout, /*decode_only=*/false);
    std::cout << result.smoother_text << result.calibration_text;
    std::cout << (args.options.smooth ? "smoothed poses: " : "poses: ") << result.poses << "\n";
    if (const auto it = result.summary.extra.find("lcm"); it != result.summary.extra.end()) {
      std::cout << "lcm: " << (*it)["published"] << " messages published, " << (*it)["failures"] << " failed\n";
    }
    if (!result.forward_accuracy_text.empty()) std::cout << "forward filter:\n" << result.forward_accuracy_text << "smoothed:\n";
    std::cout << result.accuracy_text;
  }
  if (result.imu_time_backwards > 0) {
    std::cerr << "navfuse: warning: " << result.imu_time_backwards
              << " IMU samples rejected as time_backwards (their time went back: a log concatenated "
                 "with itself, or a clock reset?); the outputs do not cover them\n";
  }
  if (result.summary.interrupted_by != 0) {
    std::cerr << "navfuse: " << (args.options.smooth ? "smooth" : "replay") << " interrupted by signal "
              << result.summary.interrupted_by
              << ": outputs and summary cover the part processed\n";
    return interrupted_exit_code(result.summary.interrupted_by);
  }
  if (!result.failure.empty()) {
    return nothing_useful(args.options.smooth ? "smooth" : "replay", result.failure, args.allow_empty);
  }
  return 0;
}

}  // namespace

namespace {

// replay and smooth take the same inputs, outputs and truth: one definition of their options.
void add_fusion_command(CLI::App& root, int& exit_code, const char* name, const char* description, bool smooth) {
  auto args = std::make_shared<ReplayArgs>();
  ReplayOptions& o = args->options;
  o.smooth = smooth;
  CLI::App* sub = root.add_subcommand(name, description);
  add_inputs(sub, o.inputs,
             "[FORMAT:]PATH, several merged by measurement time; FORMAT one of fe, mip, vn, unicore, rtklib, "
             "imutxt (detected when omitted)");
  sub->add_option("--recording", o.recording_dir,
                  "Replay a `navfuse run --record DIR` recording in the live run's order (with its config "
                  "unless --config is given): the live run's outputs again, byte for byte");
  add_gps_week_option(sub, o.gps_week);
  sub->add_option("--config", o.config_path, "YAML configuration (default: the device profile of the first input)");
  sub->add_option("--fe-out", o.fe_out, "Write FusionEngine Pose/PoseAux/GNSSInfo/IMUOutput to this file");
  sub->add_option("--mip-out", o.mip_out, "Write MIP filter (0x82) packets to this file");
  sub->add_option("--csv", o.csv_out, "Write one CSV row per pose to this file");
  sub->add_option("--nmea-out", o.nmea_out, "Write NMEA GGA/RMC/HDT sentences (at most 10 Hz) to this file");
  sub->add_option("--innovations-csv", o.innovations_csv,
                  "Write one CSV row per aiding measurement: result, NIS, residuals and their predicted std");
  args->lcm = sub->add_option("--lcm", args->lcm_url,
                              "Publish NAVFUSE_POSE and NAVFUSE_IMU at the pose rate on LCM [URL]")
                   ->expected(0, 1);
  sub->add_option("--summary-json", args->summary_json, "Write the summary as JSON to this file");
  sub->add_option("--truth", o.truth_path,
                  "Reference to report the error against: [csv:|rtklib:|nav:]PATH (navfuse sim --truth CSV, "
                  "RTKLIB .pos at the antenna, KF-GINS .nav)");
  sub->add_option("--rate", args->rate_hz, "Pose output rate in Hz, overriding output.rate_hz (0 = every IMU sample)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--gnss-outage", o.gnss_outage,
                  "Withhold GNSS in windows PERIOD_S:DURATION_S[:START_S] from the first IMU sample (e.g. 30:10)");
  sub->add_flag("--allow-truncated", o.allow_truncated, "Replay an input whose last frame is cut off");
  add_quiet_flag(sub, args->quiet, "summary, accuracy or progress bar");
  if (smooth) {
    sub->add_option("--calibration-out", o.calibration_out,
                    "Calibrate lever arm, IMU mounting, IMU time offset, odometer scale and IMU biases over the "
                    "log (Ceres batch fit from the smoothed solution); write the config with them to this file");
    sub->add_option("--calibration-rounds", o.calibration_rounds,
                    "With --calibration-out: smooth and calibrate again from the calibrated installation, at most "
                    "this many times in all (stops when a round changes nothing)")
        ->check(CLI::Range(1, 10))
        ->capture_default_str();
    add_examples(sub, {{"the demo drive smoothed, scored against truth (forward and smoothed), poses to CSV",
                        "navfuse smooth --config data/demo/vn300.yaml data/demo/vn300.vnb data/demo/vn300_wheel.p1log "
                        "--truth data/demo/truth.csv --csv smoothed.csv"},
                       {"30 s GNSS outages every 60 s bridged by the smoother",
                        "navfuse smooth --config data/demo/vn300.yaml data/demo/vn300.vnb --gnss-outage 60:30 "
                        "--truth data/demo/truth.csv"}});
  } else {
    add_examples(sub, {{"the demo drive with its wheel speeds, scored against truth, poses to CSV",
                        "navfuse replay --config data/demo/vn300.yaml data/demo/vn300.vnb data/demo/vn300_wheel.p1log "
                        "--truth data/demo/truth.csv --csv pose.csv"},
                       {"a `navfuse run --record rec` recording: the live run's outputs again",
                        "navfuse replay --recording rec --fe-out pose.p1log --mip-out pose.mip"}});
  }
  sub->add_flag("--allow-empty", args->allow_empty, kAllowEmptyHelp);
  sub->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace

void add_replay_command(CLI::App& root, int& exit_code) {
  add_fusion_command(root, exit_code, "replay", "Replay logs through the filter as fast as possible", false);
  add_fusion_command(root, exit_code, "smooth",
                     "Replay logs through the filter, then smooth the whole pass (RTS) into the outputs", true);
}

}  // namespace navfuse::apps

#include "apps/replay/replay_command.hpp"

#include <iostream>
#include <memory>

#include "apps/common/command_error.hpp"
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
    if (!args.lcm_url.empty() && args.lcm_url.find("://") == std::string::npos) {
      throw CommandError("--lcm: '" + args.lcm_url + "' is not an LCM URL (e.g. udpm://239.255.76.67:7667?ttl=0); "
                         "write --lcm=URL, or put --lcm after the inputs");
    }
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
    std::cout << "poses: " << result.poses << "\n";
    if (const auto it = result.summary.extra.find("lcm"); it != result.summary.extra.end()) {
      std::cout << "lcm: " << (*it)["published"] << " messages published, " << (*it)["failures"] << " failed\n";
    }
    std::cout << result.accuracy_text;
  }
  if (result.imu_time_backwards > 0) {
    std::cerr << "navfuse: warning: " << result.imu_time_backwards
              << " IMU samples rejected as time_backwards (their time went back: a log concatenated "
                 "with itself, or a clock reset?); the outputs do not cover them\n";
  }
  if (result.summary.interrupted_by != 0) {
    std::cerr << "navfuse: replay interrupted by signal " << result.summary.interrupted_by
              << ": outputs and summary cover the part processed\n";
    return interrupted_exit_code(result.summary.interrupted_by);
  }
  if (!result.failure.empty()) return nothing_useful("replay", result.failure, args.allow_empty);
  return 0;
}

}  // namespace

void add_replay_command(CLI::App& root, int& exit_code) {
  auto args = std::make_shared<ReplayArgs>();
  ReplayOptions& o = args->options;
  CLI::App* sub = root.add_subcommand("replay", "Replay logs through the filter as fast as possible");
  sub->add_option("INPUT", o.inputs, "[FORMAT:]PATH, several merged by measurement time; FORMAT one of fe, mip, vn, "
                                     "unicore, rtklib, imutxt (detected when omitted)")
      ->required();
  add_gps_week_option(sub, o.gps_week);
  sub->add_option("--config", o.config_path, "YAML configuration (default: the device profile of the first input)");
  sub->add_option("--fe-out", o.fe_out, "Write FusionEngine Pose/PoseAux/GNSSInfo/IMUOutput to this file");
  sub->add_option("--mip-out", o.mip_out, "Write MIP filter (0x82) packets to this file");
  sub->add_option("--csv", o.csv_out, "Write one CSV row per pose to this file");
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
  sub->add_flag("--allow-empty", args->allow_empty, kAllowEmptyHelp);
  sub->add_flag("-q,--quiet", args->quiet, "Print only errors");
  sub->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace navfuse::apps

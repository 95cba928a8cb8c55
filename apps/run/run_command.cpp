#include "apps/run/run_command.hpp"

#include <csignal>
#include <iostream>
#include <memory>

#include "apps/common/command_error.hpp"
#include "apps/common/summary.hpp"
#include "apps/run/nav_process.hpp"
#include "apps/run/run_log.hpp"
#include "apps/run/run_options.hpp"
#include "apps/run/termination_signals.hpp"

namespace navfuse::apps {
namespace {

constexpr int kSignalPollMs = 50;  // also how soon the end of all (file) inputs is noticed

int run_nav_process(const RunOptions& options) {
  TerminationSignals signals;  // before any thread exists, so every thread inherits the mask
  NavProcess process(options);
  process.start();
  log_event("running; SIGINT or SIGTERM to stop");
  for (;;) {
    if (const int sig = signals.wait(kSignalPollMs); sig != 0) {
      log_event(sig == SIGINT ? "SIGINT: stopping" : "SIGTERM: stopping");
      break;
    }
    if (process.finished()) {
      log_event("every input has ended: stopping");
      break;
    }
  }
  process.stop();
  Summary summary = process.summary();
  const std::vector<std::string> output_errors = process.output_errors();
  if (!output_errors.empty()) summary.extra["output_errors"] = output_errors;
  if (!options.summary_json.empty()) write_json_file(options.summary_json, summary.to_json(/*decode_only=*/false));
  if (!options.quiet) summary.print(std::cerr, /*decode_only=*/false);
  // An output file that lost bytes is a failed run, whatever else went well (issue 15.7).
  if (!output_errors.empty()) {
    std::string what = output_errors.front();
    if (output_errors.size() > 1) what += " (and " + std::to_string(output_errors.size() - 1) + " more outputs)";
    throw CommandError(what);
  }
  return 0;
}

}  // namespace

void add_run_command(CLI::App& root, int& exit_code) {
  auto opt = std::make_shared<RunOptions>();
  CLI::App* sub = root.add_subcommand("run", "Live nav process: device streams in, poses out (LCM, FusionEngine, MIP)");
  sub->add_option("--config", opt->config_path, "YAML configuration (DESIGN.md keys)")->required();
  sub->add_option("--in", opt->inputs,
                  "Input [FORMAT:]URI, repeatable; FORMAT one of fe, mip, vn, unicore (detected when omitted); "
                  "URI serial:/dev/ttyUSB0?baud=921600, tcp://host:port, tcp-listen://:port, udp://:port, file:PATH")
      ->required();
  sub->add_option("--fe-out", opt->fe_out, "FusionEngine output URI (also accepts FusionEngine commands)");
  sub->add_option("--mip-out", opt->mip_out, "MIP 0x82 output URI (also accepts MIP commands and 0x13 aiding)");
  sub->add_option("--lcm", opt->lcm_url, "Publish NAVFUSE_POSE/STATUS/IMU/GNSS and take NAVFUSE_AID_* on LCM [URL]")
      ->expected(0, 1);
  sub->add_flag("--configure-device", opt->configure_device,
                "Send each input device its set-up sequence so that it streams what fusion needs");
  sub->add_option("--status-interval", opt->status_interval_s, "NAVFUSE_STATUS period, s (default 1)");
  sub->add_option("--summary-json", opt->summary_json, "At exit, write the run summary as JSON to this file");
  sub->add_flag("--quiet", opt->quiet, "Print only errors and events, no summary at exit");
  sub->callback([opt, sub, &exit_code] {
    opt->lcm = sub->count("--lcm") > 0;
    exit_code = run_nav_process(*opt);
  });
}

}  // namespace navfuse::apps

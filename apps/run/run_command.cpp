#include "apps/run/run_command.hpp"

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "apps/common/command_error.hpp"
#include "apps/common/command_help.hpp"
#include "apps/common/summary.hpp"
#include "apps/run/nav_process.hpp"
#include "apps/run/ntrip_protocol.hpp"
#include "apps/run/process_priority.hpp"
#include "apps/run/run_log.hpp"
#include "apps/run/run_options.hpp"
#include "apps/run/termination_signals.hpp"

namespace navfuse::apps {
namespace {

constexpr int kSignalPollMs = 50;  // also how soon the end of all (file) inputs is noticed

int run_nav_process(const RunOptions& options) {
  TerminationSignals signals;  // before any thread exists, so every thread inherits the mask
  // Also before any thread: they inherit the scheduling policy.
  const PriorityOutcome priority = apply_priority({options.rt_priority, options.lock_memory});
  for (const std::string& line : priority.report) log_event(line);
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
    if (!process.setup_error().empty()) {
      log_event("a device is not set up as configured: stopping");
      break;
    }
  }
  process.stop();
  Summary summary = process.summary();
  const std::vector<std::string> output_errors = process.output_errors();
  if (!output_errors.empty()) summary.extra["output_errors"] = output_errors;
  if (!options.summary_json.empty()) write_json_file(options.summary_json, summary.to_json(/*decode_only=*/false));
  if (!options.quiet) summary.print(std::cerr, /*decode_only=*/false);
  // A device that refused its set-up or holds other settings than the config's is a failed run:
  // its data were not what navfuse was configured for (issue 17).
  if (const std::string setup = process.setup_error(); !setup.empty()) throw CommandError(setup);
  // An output file that lost bytes is a failed run, whatever else went well (issue 15.7).
  if (!output_errors.empty()) {
    std::string what = output_errors.front();
    if (output_errors.size() > 1) what += " (and " + std::to_string(output_errors.size() - 1) + " more outputs)";
    throw CommandError(what);
  }
  return 0;
}

double parse_speed(const std::string& text) {
  if (text.empty()) return 1.0;
  char* end = nullptr;
  const double speed = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(speed > 0.0) || !std::isfinite(speed)) {
    throw CommandError("--realtime: '" + text + "' is not a speed > 0 (times real time, e.g. 1 or 10); "
                       "write --realtime=SPEED, or put --realtime after the inputs");
  }
  return speed;
}

}  // namespace

void add_run_command(CLI::App& root, int& exit_code) {
  struct Args {
    RunOptions options;
    std::vector<std::string> in_options;  // --in (DESIGN.md contract), before the positional INPUTs
    std::vector<std::string> positional;
    std::string realtime;
  };
  auto args = std::make_shared<Args>();
  RunOptions* opt = &args->options;
  CLI::App* sub = root.add_subcommand("run", "Live nav process: device streams in, poses out (LCM, FusionEngine, MIP)");
  sub->add_option("--config", opt->config_path, "YAML configuration (DESIGN.md keys)")->required();
  const std::string input_help =
      "Input [FORMAT:]URI; FORMAT one of fe, mip, vn, unicore (detected when omitted); URI serial:/dev/ttyUSB0?baud=921600, "
      "tcp://host:port, tcp-listen://:port, udp://:port, file:PATH or a PATH";
  add_inputs(sub, args->positional, input_help);
  sub->add_option("--in", args->in_options, input_help + " (repeatable; the same as INPUT)");
  sub->add_option("--fe-out", opt->fe_out, "FusionEngine output URI (also accepts FusionEngine commands)");
  sub->add_option("--mip-out", opt->mip_out, "MIP 0x82 output URI (also accepts MIP commands and 0x13 aiding)");
  sub->add_option("--nmea-out", opt->nmea_out, "NMEA GGA/RMC/HDT output URI (at most 10 Hz), e.g. for an autopilot");
  sub->add_option("--csv", opt->csv_out, "Write one CSV row per pose to this file (as replay --csv)");
  CLI::Option* lcm =
      sub->add_option("--lcm", opt->lcm_url, "Publish NAVFUSE_POSE/STATUS/IMU/GNSS and take NAVFUSE_AID_* on LCM [URL]")
          ->expected(0, 1);
  sub->add_flag("--configure-device", opt->configure_device,
                "Send each input device its set-up sequence so that it streams what fusion needs, and the "
                "installation geometry of the config (VN-300: Reg 57 antenna A offset, Reg 93 baseline; CV7: "
                "0x0D,0x54 antenna offsets, 0x0D,0x61 speed lever arm; FusionEngine: device, GNSS and GNSS aux "
                "lever arms and the IMUOutput/Pose/GNSSInfo rates), each read back and compared; a refusal or a mismatch ends the run with an error. "
                "Mounting is not sent: navfuse rotates the IMU data by imu.mounting_rpy_deg itself (a VN-300 "
                "Reg 26 rotation would also need a reset to take effect)");
  sub->add_option("--status-interval", opt->status_interval_s, "NAVFUSE_STATUS period, s (default 1)");
  sub->add_option("--summary-json", opt->summary_json, "At exit, write the run summary as JSON to this file");
  sub->add_option("--record", opt->record_dir,
                  "Write every input's raw bytes with host receive times into this new directory "
                  "(navfuse replay --recording DIR gives this run's outputs again)");
  CLI::Option* realtime =
      sub->add_option("--realtime", args->realtime,
                      "Feed file inputs at the pace of their timestamps [SPEED times real time, default 1]")
          ->expected(0, 1);
  sub->add_option("--corrections", opt->corrections,
                  "RTK corrections to forward to a receiver: " + std::string(kCorrectionsSourceForms) +
                      " (NTRIP 2.0 unless version=1; gga=SECONDS reports navfuse's position to the caster as "
                      "an NMEA GGA sentence that often, as network-RTK/VRS mountpoints need; default never)");
  sub->add_option("--corrections-to", opt->corrections_to,
                  "The input (0 = the first) whose port the corrections are written to (default 0)");
  sub->add_option("--rt-priority", opt->rt_priority,
                  "Run under SCHED_FIFO at this priority (1-99); reported when not permitted")
      ->check(CLI::Range(1, 99));
  sub->add_flag("--lock-memory", opt->lock_memory, "Lock all memory in RAM (mlockall); reported when not permitted");
  add_quiet_flag(sub, opt->quiet, "summary at exit (events are still logged)");
  add_examples(sub, {{"a VN-300 on a serial port: poses on LCM, FusionEngine on TCP port 30201, raw input recorded",
                      "navfuse run --config data/config/vn300.yaml vn:serial:/dev/ttyUSB0?baud=921600 --lcm "
                      "--fe-out tcp-listen://:30201 --record rec"},
                     {"the demo drive and its wheel speeds delivered as live devices would, at 10x real time",
                      "navfuse run --config data/demo/vn300.yaml data/demo/vn300.vnb data/demo/vn300_wheel.p1log "
                      "--realtime 10 --lcm --summary-json run.json"}});
  sub->callback([args, lcm, realtime, &exit_code] {
    RunOptions& o = args->options;
    o.inputs = args->in_options;
    o.inputs.insert(o.inputs.end(), args->positional.begin(), args->positional.end());
    o.lcm = lcm->count() > 0;
    if (o.lcm) check_lcm_url(o.lcm_url);
    if (realtime->count() > 0) o.realtime_speed = parse_speed(args->realtime);
    exit_code = run_nav_process(o);
  });
}

}  // namespace navfuse::apps

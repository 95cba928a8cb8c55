#include "apps/bench/bench_command.hpp"

#include <iostream>
#include <memory>

#include "apps/bench/bench.hpp"
#include "apps/common/command_help.hpp"
#include "apps/common/command_error.hpp"
#include "apps/common/empty_run.hpp"
#include "apps/common/gps_week_option.hpp"
#include "apps/common/interrupt_signals.hpp"

namespace navfuse::apps {

void add_bench_command(CLI::App& root, int& exit_code) {
  struct Args {
    bench::BenchOptions options;
    std::vector<std::string> fail_above;
    bool quiet = false;
    bool allow_empty = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = root.add_subcommand(
      "bench", "Compare navfuse with the device's own solution in the same log (and both with truth)");
  add_inputs(cmd, args->options.inputs, "[FORMAT:]PATH of each log (fe, mip, vn, unicore, rtklib, imutxt)")->required();
  add_gps_week_option(cmd, args->options.gps_week);
  cmd->add_option("--config", args->options.config_path, "YAML configuration (default: the device's profile)");
  cmd->add_option("--truth", args->options.truth_path, "truth CSV (navfuse sim --truth) to compare both with");
  cmd->add_option("--reference", args->options.reference,
                  "smoothed: also compare navfuse's forward filter and the device with navfuse's smoothed (RTS) "
                  "solution of the same log, the best reference a log without truth has");
  cmd->add_option("--report", args->options.report_dir, "folder for report.html, metrics.json and CSVs")->required();
  cmd->add_option("--fail-above", args->fail_above,
                  "METRIC=VALUE: exit 3 when a metrics.json value exceeds VALUE (repeatable), e.g. "
                  "navfuse_vs_truth.horizontal_m.rms=0.5");
  cmd->add_option("--max-gap", args->options.max_gap_s,
                  "longest interval (s) interpolated across (default: 3 median sample intervals)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--no-html", [args](std::int64_t) { args->options.html = false; },
                "write metrics.json and CSVs only (no Python needed)");
  cmd->add_flag("--allow-truncated", args->options.allow_truncated, "accept a log whose last frame is cut off");
  add_quiet_flag(cmd, args->quiet, "summary, notes or progress bar");
  add_examples(cmd, {{"navfuse against the Point One Atlas's own solution in its log, metrics only",
                      "navfuse bench --config data/demo/fusionengine.yaml data/demo/atlas.p1log --report bench-out --no-html"},
                     {"the demo CV7 log: navfuse and the CV7's own filter, both against the simulated truth",
                      "navfuse bench --config data/demo/cv7.yaml data/demo/cv7.mip --truth data/demo/truth.csv "
                      "--report bench-cv7"}});
  cmd->add_flag("--allow-empty", args->allow_empty, kAllowEmptyHelp);
  cmd->callback([args, &exit_code] {
    for (const auto& a : args->fail_above) args->options.fail_above.push_back(bench::parse_fail_threshold(a));
    args->options.progress = !args->quiet;
    const InterruptSignals signals;
    args->options.interrupt = &InterruptSignals::received();
    bench::BenchResult result;
    try {
      result = bench::run_bench(args->options);
    } catch (const CommandError& e) {
      exit_code = tolerate_empty(e, args->allow_empty);
      return;
    }
    if (!args->quiet) {
      for (const auto& note : result.notes) std::cerr << "navfuse bench: " << note << "\n";
    }
    for (const auto& warning : result.warnings) std::cerr << "navfuse bench: warning: " << warning << "\n";
    if (!args->quiet || result.interrupted_by != 0) {
      std::cout << result.summary_text << "report: " << args->options.report_dir << "/"
                << (args->options.html ? "report.html" : "metrics.json") << "\n";
    }
    for (const auto& line : result.exceeded) std::cerr << "navfuse bench: bound exceeded: " << line << "\n";
    if (result.interrupted_by != 0) {
      exit_code = interrupted_exit_code(result.interrupted_by);
    } else {
      exit_code = result.exceeded.empty() ? 0 : bench::kExitThresholdExceeded;
    }
  });
}

}  // namespace navfuse::apps

// navfuse: GNSS/INS fusion engine command line. Subcommands (DESIGN.md, contract): replay, run,
// decode, bench, aid, sim; plus config. Each lives in apps/<name>/ and registers itself here.
#include <csignal>
#include <iostream>

#include <CLI/CLI.hpp>

#include "apps/aid/aid_command.hpp"
#include "apps/bench/bench_command.hpp"
#include "apps/common/command_error.hpp"
#include "apps/configcmd/config_command.hpp"
#include "apps/decode/decode_command.hpp"
#include "apps/replay/calibration_hook.hpp"
#include "apps/replay/replay_command.hpp"
#include "apps/run/build_info.hpp"
#include "apps/run/run_command.hpp"
#include "apps/simcmd/sim_command.hpp"
#include "calibration/calibration_problem.hpp"

int main(int argc, char** argv) {
  // A pipe whose reader went away is a write error each output reports (EPIPE, exit non-zero),
  // not a silent death by SIGPIPE half-way through a file (issue 15, item 7).
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{"navfuse: loosely-coupled GNSS/INS fusion engine"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "navfuse " + std::string(navfuse::apps::navfuse_version()));
  int exit_code = 0;
  // The Ceres calibration behind `smooth --calibration-out` (apps/replay/calibration_hook.hpp).
  navfuse::apps::set_calibration_solver([](const navfuse::calib::CalibrationLog& log) { return navfuse::calib::calibrate(log); });
  navfuse::apps::add_decode_command(app, exit_code);
  navfuse::apps::add_replay_command(app, exit_code);
  navfuse::apps::add_bench_command(app, exit_code);
  navfuse::apps::add_aid_command(app, exit_code);
  navfuse::apps::add_run_command(app, exit_code);
  navfuse::apps::add_sim_command(app, exit_code);
  navfuse::apps::add_config_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const navfuse::apps::CommandError& e) {
    std::cerr << "navfuse: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "navfuse: error: " << e.what() << "\n";
    return 1;
  }
  // The summary and decode's rows go to standard output: a failed write there fails too.
  if (!std::cout.flush()) {
    std::cerr << "navfuse: error: cannot write standard output\n";
    return exit_code != 0 ? exit_code : 1;
  }
  return exit_code;
}

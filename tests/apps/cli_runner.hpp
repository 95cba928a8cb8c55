// Runs navfuse subcommands in-process the way apps/main.cpp does (same CLI11 parse, same
// CommandError handling), so tests check exit codes and the one-line error messages users see.
#pragma once

#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/common/command_error.hpp"
#include "apps/decode/decode_command.hpp"
#include "apps/replay/replay_command.hpp"
#include "apps/simcmd/sim_command.hpp"

namespace navfuse::apps::testing {

struct CliResult {
  int exit_code = 0;
  std::string error;  // what main() prints after "navfuse: error: "
};

inline CliResult run_cli(std::vector<std::string> args) {
  CLI::App app{"navfuse"};
  app.require_subcommand(1);
  int exit_code = 0;
  add_decode_command(app, exit_code);
  add_replay_command(app, exit_code);
  add_sim_command(app, exit_code);
  std::vector<const char*> argv{"navfuse"};
  for (const auto& a : args) argv.push_back(a.c_str());
  CliResult r;
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    r.exit_code = exit_code;
  } catch (const CLI::ParseError& e) {
    r.exit_code = e.get_exit_code() == 0 ? 0 : 2;
    r.error = e.what();
  } catch (const CommandError& e) {
    r.exit_code = e.exit_code();
    r.error = e.what();
  } catch (const std::exception& e) {
    r.exit_code = 1;
    r.error = e.what();
  }
  return r;
}

}  // namespace navfuse::apps::testing

// `navfuse run --config F --in URI... [--fe-out URI] [--mip-out URI] [--lcm [URL]]
//  [--configure-device]`: the live nav process (nav_process.hpp) until SIGINT or SIGTERM, or until
// every input has ended (file inputs). Exits 0 after flushing its outputs.
#pragma once

#include <CLI/CLI.hpp>

namespace navfuse::apps {

void add_run_command(CLI::App& root, int& exit_code);

}  // namespace navfuse::apps

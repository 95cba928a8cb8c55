// `navfuse replay [--config F] INPUT... [--fe-out F.p1log] [--mip-out F.mip] [--csv F.csv]
//                 [--summary-json F] [--truth F.csv] [--rate HZ] [--allow-truncated] [--quiet]`
// (DESIGN.md, contract): see replay.hpp for what it does.
// `navfuse smooth` takes the same arguments: the run is recorded and smoothed (ReplayOptions::smooth).
#pragma once

#include <CLI/CLI.hpp>

namespace navfuse::apps {

// Adds the replay and smooth subcommands to `root`; its callback stores the exit status in `exit_code`.
void add_replay_command(CLI::App& root, int& exit_code);

}  // namespace navfuse::apps

// `navfuse aid KIND [values...] [--lcm URL]`: send external aiding (position, velocity, heading,
// speed) to a running nav process over LCM, from the command line or from a CSV of rows.
#pragma once

#include <CLI/CLI.hpp>

namespace navfuse::apps {

void add_aid_command(CLI::App& root, int& exit_code);

}  // namespace navfuse::apps

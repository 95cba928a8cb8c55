// `navfuse bench INPUT... [--config F] [--truth F.csv] --report DIR [--fail-above METRIC=VALUE]...
//                [--max-gap S] [--no-html] [--allow-truncated] [--quiet]`
// (DESIGN.md, contract): see bench.hpp for what it does. Exit 0 on success, 1 with a one-line
// reason on bad input, 3 when a --fail-above bound is exceeded (the report is written anyway).
#pragma once

#include <CLI/CLI.hpp>

namespace navfuse::apps {

// Adds the subcommand to `root`; its callback stores the exit status in `exit_code`.
void add_bench_command(CLI::App& root, int& exit_code);

}  // namespace navfuse::apps

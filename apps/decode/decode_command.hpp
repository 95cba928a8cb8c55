// `navfuse decode INPUT [--format csv|jsonl] [--out F] [--summary-json F]`: every frame of a log
// with its decoded fields, and the normalised measurements, as CSV or JSON lines.
#pragma once

#include <CLI/CLI.hpp>

namespace navfuse::apps {

// Adds the subcommand to `root`; its callback stores the exit status in `exit_code`.
void add_decode_command(CLI::App& root, int& exit_code);

}  // namespace navfuse::apps

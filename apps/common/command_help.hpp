// What every navfuse command's command line has in common, so that it is spelled once: the
// -q,--quiet flag, the positional INPUT... of the commands that read logs or links, and the
// worked examples that end each --help (issue 17, "first contact").
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace navfuse::apps {

// -q,--quiet; `what` says what the command then leaves out.
CLI::Option* add_quiet_flag(CLI::App* command, bool& quiet, const std::string& what);

// The positional INPUT...: `description` says what one input is.
CLI::Option* add_inputs(CLI::App* command, std::vector<std::string>& inputs, const std::string& description);

// --lcm takes an optional URL, so `--lcm LOG` would read the log as the URL: refused, with the fix.
void check_lcm_url(const std::string& url);

struct HelpExample {
  const char* what;     // one line: what it does
  const char* command;  // the command line, from `navfuse`
};
// Ends the command's --help with its examples.
void add_examples(CLI::App* command, std::initializer_list<HelpExample> examples);

}  // namespace navfuse::apps

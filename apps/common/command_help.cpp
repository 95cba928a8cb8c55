#include "apps/common/command_help.hpp"

#include "apps/common/command_error.hpp"

namespace navfuse::apps {

CLI::Option* add_quiet_flag(CLI::App* command, bool& quiet, const std::string& what) {
  return command->add_flag("-q,--quiet", quiet, "Print only errors: no " + what);
}

CLI::Option* add_inputs(CLI::App* command, std::vector<std::string>& inputs, const std::string& description) {
  return command->add_option("INPUT", inputs, description);
}

void check_lcm_url(const std::string& url) {
  if (!url.empty() && url.find("://") == std::string::npos) {
    throw CommandError("--lcm: '" + url + "' is not an LCM URL (e.g. udpm://239.255.76.67:7667?ttl=0); "
                       "write --lcm=URL, or put --lcm after the inputs");
  }
}

void add_examples(CLI::App* command, std::initializer_list<HelpExample> examples) {
  std::string text = "Examples:\n";
  for (const HelpExample& e : examples) text += std::string("  # ") + e.what + "\n  " + e.command + "\n";
  command->footer(text);
}

}  // namespace navfuse::apps

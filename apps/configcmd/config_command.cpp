#include "apps/configcmd/config_command.hpp"

#include <iostream>
#include <memory>

#include "apps/common/command_error.hpp"
#include "apps/common/command_help.hpp"
#include "core/config/config.hpp"

namespace navfuse::apps {
namespace {

struct ConfigOptions {
  bool dump = false;
  bool quiet = false;
  std::string config_path;
  std::string device;
};

}  // namespace

std::string dump_config(const std::string& config_path, const std::string& device) {
  if (!config_path.empty() && !device.empty()) {
    throw CommandError("config: give --config F or --device NAME, not both (F's `device:` key chooses the profile)");
  }
  try {
    if (!config_path.empty()) return config::to_yaml(config::load_from_file(config_path));
    auto profile = config::DeviceProfile::kGeneric;
    if (!device.empty()) {
      const auto p = config::device_profile_from_string(device);
      if (!p) throw CommandError("config: --device: expected one of cv7, vn300, um220, fusionengine, generic, got '" + device + "'");
      profile = *p;
    }
    return config::to_yaml(config::defaults_for(profile));
  } catch (const config::ConfigError& e) {
    throw CommandError(e.what());
  }
}

void add_config_command(CLI::App& root, int& exit_code) {
  auto opt = std::make_shared<ConfigOptions>();
  CLI::App* sub = root.add_subcommand("config", "Print the effective configuration: every key with its value or default");
  sub->add_flag("--dump", opt->dump, "print the configuration as YAML (loadable with --config); without it the config is only checked");
  sub->add_option("--config", opt->config_path, "YAML configuration file (default: the device profile's defaults)");
  sub->add_option("--device", opt->device, "defaults of this device profile: cv7 | vn300 | um220 | fusionengine | generic");
  add_quiet_flag(sub, opt->quiet, "the line saying the configuration is valid (errors still go to stderr)");
  add_examples(sub, {{"every key with its generic default", "navfuse config --dump"},
                     {"what the demo config sets, with everything it leaves at the default",
                      "navfuse config --dump --config data/demo/vn300.yaml"}});
  sub->callback([opt, &exit_code] {
    const std::string yaml = dump_config(opt->config_path, opt->device);
    if (opt->dump) {
      std::cout << yaml;
    } else if (!opt->quiet) {
      std::cout << (opt->config_path.empty() ? std::string("defaults") : opt->config_path)
                << ": valid configuration (--dump prints it)\n";
    }
    exit_code = 0;
  });
}

}  // namespace navfuse::apps

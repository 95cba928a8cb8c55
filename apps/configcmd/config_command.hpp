// `navfuse config [--dump] [--config F | --device NAME]`: checks a configuration; with --dump prints
// the effective configuration as YAML, every key with its value (from F, or the device profile's
// default) and its meaning; the output loads back to the same configuration
// (core/config/config_writer.cpp).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace navfuse::apps {

void add_config_command(CLI::App& root, int& exit_code);

// The text `config --dump` prints; throws CommandError naming the key on a bad config.
std::string dump_config(const std::string& config_path, const std::string& device);

}  // namespace navfuse::apps

// The one-line message a config raises, for the loader tests.
#pragma once

#include <string>

#include "core/config/config.hpp"

namespace navfuse::config::test {

// The message of the ConfigError `yaml` raises ("" when it loads), source named "config.yaml".
inline std::string error_of(const std::string& yaml) {
  try {
    load_from_string(yaml, "config.yaml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace navfuse::config::test

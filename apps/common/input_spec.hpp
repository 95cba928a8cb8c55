// INPUT arguments of the form [FORMAT:]PATH (DESIGN.md, contract): FORMAT one of the registered
// front-ends; without it the format is detected from the first bytes of the file.
#pragma once

#include <string>

#include "frontends/common/frontend_info.hpp"

namespace navfuse::apps {

struct InputSpec {
  std::string path;
  const frontends::FrontendInfo* frontend = nullptr;  // resolved (given or detected)
  bool format_detected = false;                       // true when not given by prefix
};

// Parses the argument and resolves the front-end; throws CommandError with a one-line reason
// for an unknown format prefix, a missing/unreadable/empty file, or an undetectable format.
InputSpec resolve_input(const std::string& argument);

}  // namespace navfuse::apps

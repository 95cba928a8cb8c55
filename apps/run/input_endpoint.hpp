// `--in [FORMAT:]URI` of `navfuse run` (DESIGN.md, contract): FORMAT one of the registered
// front-ends (vn, mip, fe, unicore), URI a core/io transport URI. Without FORMAT the format is
// detected from the first bytes received. A bare path (no scheme) is read as file:PATH, so that
// `--in vn:log.bin` works like replay's INPUT.
#pragma once

#include <string>

#include "core/io/uri.hpp"
#include "frontends/common/frontend_info.hpp"

namespace navfuse::apps {

struct InputEndpoint {
  std::string text;                                   // as given, for messages and status
  const frontends::FrontendInfo* frontend = nullptr;  // nullptr: detect from the bytes
  io::Uri uri;
};

// Throws CommandError with a one-line reason: unknown format prefix, bad URI.
InputEndpoint parse_input_endpoint(const std::string& argument);

// An output URI (`--fe-out`, `--mip-out`): a transport URI, or a bare path read as file:PATH.
io::Uri parse_output_uri(const std::string& argument, const char* option);

}  // namespace navfuse::apps

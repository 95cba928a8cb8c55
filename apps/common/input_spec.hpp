// INPUT arguments of the form [FORMAT:]PATH (DESIGN.md, contract): FORMAT one of the registered
// front-ends; without it the format is detected from the first bytes of the file.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frontends/common/frontend_info.hpp"

namespace navfuse::apps {

struct InputSpec {
  std::string path;
  const frontends::FrontendInfo* frontend = nullptr;  // resolved (given or detected)
  bool format_detected = false;                       // true when not given by prefix
  // For formats timed by seconds of week only (imutxt): the GPS week to decode them in.
  std::optional<std::int32_t> gps_week = std::nullopt;
  // The first bytes (up to kProbeBytes), read once for detection and for the week inference.
  std::vector<std::uint8_t> head;
  // A pipe, FIFO or device (cat log | navfuse replay vn:/dev/stdin) cannot be read twice: it
  // stays open here, and the reader feeds `head` before going on from where detection stopped
  // (before, the first 64 KiB were lost). Null for regular files, which are reopened.
  std::shared_ptr<std::FILE> stream;
};

// Parses the argument and resolves the front-end; throws CommandError with a one-line reason
// for an unknown format prefix, a missing/unreadable/empty file, or an undetectable format.
InputSpec resolve_input(const std::string& argument);

// Resolves every argument, then gives each input whose format needs the GPS week (imutxt) the
// week: `gps_week` when given (--gps-week), else the week inferred from the other inputs
// (gps_week_inference.hpp). Throws CommandError when such an input gets no week.
std::vector<InputSpec> resolve_inputs(const std::vector<std::string>& arguments,
                                      std::optional<std::int32_t> gps_week);

// The decoder for an input: in its GPS week when the format needs one.
std::unique_ptr<frontends::StreamDecoder> make_decoder(const InputSpec& spec);

}  // namespace navfuse::apps

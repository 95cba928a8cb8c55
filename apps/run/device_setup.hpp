// `navfuse run --configure-device`: the command sequence that makes a fresh device stream what
// fusion needs, sent on the input link when it opens (and again when it is re-opened, because a
// replugged device may have lost unsaved settings). The sequences and the reading of the replies
// belong to the front-ends (FrontendInfo::setup_commands / find_refusal, e.g.
// frontends/vectornav/commands.hpp); this file only looks them up, so that a refused command is
// reported rather than silently ignored.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frontends/common/device_command.hpp"

namespace navfuse::apps {

using frontends::DeviceCommand;

// The set-up sequence for a format; empty when none is needed (or the format is unknown).
std::vector<DeviceCommand> device_setup_commands(std::string_view format);

// Looks through bytes received after a command for the device's refusal ($VNERR, $FAIL, a MIP
// NACK). Returns a one-line description of the first one found, or "" when there is none.
std::string find_refusal(std::string_view format, std::span<const std::uint8_t> reply_bytes);

}  // namespace navfuse::apps

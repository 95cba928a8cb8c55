// `navfuse run --configure-device`: the command sequence that makes a fresh device stream what
// fusion needs, sent on the input link when it opens (and again when it is re-opened, because a
// replugged device may have lost unsaved settings). The sequences and the reading of the replies
// belong to the front-ends (FrontendInfo::setup_steps / find_refusal, e.g.
// frontends/vectornav/commands_geometry.hpp); this file only looks them up, so that a refused
// command or a setting that does not read back as written is reported, and ends the run, rather
// than silently ignored.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/config/config.hpp"
#include "frontends/common/device_command.hpp"
#include "frontends/common/setup_step.hpp"

namespace navfuse::apps {

using frontends::DeviceCommand;
using frontends::SetupStep;

// The set-up sequence for a format with the installation geometry of `config`; empty when none
// is needed (or the format is unknown).
std::vector<SetupStep> device_setup_steps(std::string_view format, const config::Config& config);

// Looks through bytes received after a command for the device's refusal ($VNERR, $FAIL, a MIP
// NACK). Returns a one-line description of the first one found, or "" when there is none.
std::string find_refusal(std::string_view format, std::span<const std::uint8_t> reply_bytes);

}  // namespace navfuse::apps

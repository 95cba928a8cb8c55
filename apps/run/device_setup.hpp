// `navfuse run --configure-device`: the command sequence that makes a fresh device stream what
// fusion needs, sent on the input link when it opens (and again when it is re-opened, because a
// replugged device may have lost unsaved settings):
//   vn       VN-300 binary output registers (frontends/vectornav/commands.hpp)
//   mip      CV7 message formats and stream enables (frontends/mip/commands.hpp)
//   unicore  UM220-INS CFGMSG outputs (frontends/unicore/commands.hpp)
//   fe       none: a FusionEngine device streams poses and measurements by default.
// The sequences themselves belong to the front-ends; this file only sends them and reads the
// answers, so that a refused command is reported rather than silently ignored.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace navfuse::apps {

// One command as bytes on the wire.
using DeviceCommand = std::vector<std::uint8_t>;

// The set-up sequence for a format ("vn", "mip", "unicore", "fe"); empty when none is needed.
std::vector<DeviceCommand> device_setup_commands(std::string_view format);

// Looks through bytes received after a command for the device's refusal ($VNERR, $FAIL, a MIP
// NACK). Returns a one-line description of the first one found, or "" when there is none.
std::string find_refusal(std::string_view format, std::span<const std::uint8_t> reply_bytes);

}  // namespace navfuse::apps

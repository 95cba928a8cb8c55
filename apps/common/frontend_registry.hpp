// The protocol front-ends navfuse knows, and format detection from a stream's first bytes.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frontends/common/frontend_info.hpp"

namespace navfuse::apps {

// Every registered front-end ("fe", "mip", "vn", "unicore", "rtklib", "imutxt"), in
// detection-priority order.
const std::vector<const frontends::FrontendInfo*>& frontends_list();
// The front-end for a format name; nullptr when unknown.
const frontends::FrontendInfo* find_frontend(std::string_view format);
// "fe, mip, vn, unicore" for messages.
std::string known_formats();
// The formats navfuse can write (those with an encoder), for `navfuse sim --format`.
std::vector<std::string> writable_formats();
// The front-end a host uses to send wheel / vehicle speed to a fusion device
// (FrontendInfo::odometry_input), for `navfuse sim --wheel-out`; nullptr when none is registered.
const frontends::FrontendInfo* odometry_input_frontend();

// Bytes probed for detection.
inline constexpr std::size_t kProbeBytes = 64 * 1024;

// The front-end whose probe finds the most valid frames in `head`; nullptr when none finds any.
const frontends::FrontendInfo* detect_format(std::span<const std::uint8_t> head);

}  // namespace navfuse::apps

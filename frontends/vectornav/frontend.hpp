// Registration of the VectorNav VN-300 front-end with the apps (`navfuse decode/replay/sim`,
// INPUT prefix "vn").
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "frontends/common/frontend_info.hpp"

namespace navfuse::frontends::vectornav {

// format "vn"; probe() counts checksum-valid VectorNav frames (binary 0xFA/0xFB packets and
// $VN... sentences; other ASCII such as NMEA is not counted) in the head of a stream;
// make_decoder() returns a VnStreamDecoder, make_encoder() a VnMeasurementEncoder.
const FrontendInfo& frontend();

std::size_t probe_vectornav(std::span<const std::uint8_t> head);

}  // namespace navfuse::frontends::vectornav

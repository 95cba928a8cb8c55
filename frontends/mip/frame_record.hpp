// FrameRecord (navfuse decode's generic view) for a MIP packet: every field decoded through the
// layout tables with wire units in the names, prefixed by the field's name
// ("scaled_accel.accel_x_g"); undescribed fields appear as hex.
#pragma once

#include "frontends/common/stream_decoder.hpp"
#include "frontends/mip/packet.hpp"

namespace navfuse::frontends::mip {

// Short name of a descriptor set, e.g. "0x80 sensor".
std::string_view set_name(std::uint8_t desc_set);
void build_frame_record(const PacketView& p, FrameRecord& rec);

}  // namespace navfuse::frontends::mip

// Walks every type of a binary message in payload order: groups, then types, in ascending raw
// bit order, packed without padding (ICD L697; digest §4.4).
#pragma once

#include <bit>

#include "frontends/vectornav/binary_message.hpp"
#include "frontends/vectornav/group_attitude.hpp"
#include "frontends/vectornav/group_common.hpp"
#include "frontends/vectornav/group_gnss.hpp"
#include "frontends/vectornav/group_imu.hpp"
#include "frontends/vectornav/group_ins.hpp"
#include "frontends/vectornav/group_time.hpp"

namespace navfuse::frontends::vectornav {

// FrameRecord field-name prefixes per group slot ("ins.lat_deg", "gnss2.fix", ...).
inline constexpr std::array<std::string_view, kGroupCount> kGroupPrefixes = {
    "common.", "time.", "imu.", "gnss1.", "attitude.", "ins.", "gnss2.", "gnss3."};

template <class Io>
void visit_message(Io& io, BinaryMessage& m) {
  for (std::size_t slot = 0; slot < kGroupCount; ++slot) {
    std::uint32_t t = m.header.types[slot];
    if constexpr (requires { io.set_prefix(std::string_view{}); }) io.set_prefix(kGroupPrefixes[slot]);
    while (t != 0) {
      const auto bit = static_cast<unsigned>(std::countr_zero(t));
      t &= t - 1;
      switch (slot) {
        case kSlotCommon: visit_common_type(bit, io, m); break;
        case kSlotTime: visit_time_type(bit, io, m.time); break;
        case kSlotImu: visit_imu_type(bit, io, m.imu); break;
        case kSlotGnss1: visit_gnss_type(bit, io, m.gnss[0]); break;
        case kSlotAttitude: visit_attitude_type(bit, io, m.attitude); break;
        case kSlotIns: visit_ins_type(bit, io, m.ins); break;
        case kSlotGnss2: visit_gnss_type(bit, io, m.gnss[1]); break;
        case kSlotGnss3: visit_gnss_type(bit, io, m.gnss[2]); break;
        default: break;
      }
    }
  }
}

}  // namespace navfuse::frontends::vectornav

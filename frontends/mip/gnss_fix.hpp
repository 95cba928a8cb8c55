// GNSS fix type mapping between (0x9x,0x0B) Fix Info (L5156: 0 3D, 1 2D, 2 time only, 3 none,
// 4 invalid, 5 RTK float, 6 RTK fixed, 7 differential; fix_flags bit0 SBAS, bit1 DGNSS) and core.
#pragma once

#include <cstdint>

#include "core/measurements/measurements.hpp"
#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {

inline GnssFixType fix_from_mip(std::uint8_t fix_type, std::uint16_t fix_flags) {
  switch (fix_type) {
    case gnss::kFix3d:
      if (fix_flags & gnss::kFixFlagDgnss) return GnssFixType::kDgnss;
      if (fix_flags & gnss::kFixFlagSbas) return GnssFixType::kSbas;
      return GnssFixType::kFix3D;
    case gnss::kFix2d: return GnssFixType::kFix2D;
    case gnss::kFixTimeOnly: return GnssFixType::kTimeOnly;
    case gnss::kFixRtkFloat: return GnssFixType::kRtkFloat;
    case gnss::kFixRtkFixed: return GnssFixType::kRtkFixed;
    case gnss::kFixDifferential: return GnssFixType::kDgnss;
    default: return GnssFixType::kNone;
  }
}

struct MipFix {
  std::uint8_t fix_type;
  std::uint16_t fix_flags;
};

// PPP has no MIP code: it is sent as a 3D fix. Dead reckoning is not a GNSS fix: "invalid".
inline MipFix fix_to_mip(GnssFixType fix) {
  switch (fix) {
    case GnssFixType::kNone: return {gnss::kFixNone, 0};
    case GnssFixType::kTimeOnly: return {gnss::kFixTimeOnly, 0};
    case GnssFixType::kFix2D: return {gnss::kFix2d, 0};
    case GnssFixType::kFix3D: return {gnss::kFix3d, 0};
    case GnssFixType::kDgnss: return {gnss::kFix3d, gnss::kFixFlagDgnss};
    case GnssFixType::kSbas: return {gnss::kFix3d, gnss::kFixFlagSbas};
    case GnssFixType::kRtkFloat: return {gnss::kFixRtkFloat, 0};
    case GnssFixType::kRtkFixed: return {gnss::kFixRtkFixed, 0};
    case GnssFixType::kPpp: return {gnss::kFix3d, 0};
    case GnssFixType::kDeadReckoning: return {gnss::kFixInvalid, 0};
  }
  return {gnss::kFixNone, 0};
}

}  // namespace navfuse::frontends::mip

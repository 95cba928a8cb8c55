// VectorNav binary output message layout: group and type bit numbers, the type-size table and
// the framing constants, shared by the framer, the decoder and the encoder so that they cannot
// disagree (VN-300 ICD Firmware v1.1.0.1, §2.1-2.9 and Appendix B.1; digest §4-§5).
//
// Bit numbering is RAW (errata A1, digest §10, ICD L5361/L5365): a table offset k is bit k of
// the concatenated group bytes / type words, extension bits included. So Gnss3 is group bit 12
// (second group byte, bit 4) and GnssRawMeas is type bit 16 (second type word, bit 0). The
// worked example of B.1 (L5371-5379) uses a different numbering; its wire bytes still parse.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace navfuse::frontends::vectornav {

// Framing constants (ICD §2.1.3 L692-699, Appendix B.1).
inline constexpr std::uint8_t kSyncBinary = 0xFA;   // L696
inline constexpr std::uint8_t kSyncSplit = 0xFB;    // L5403
inline constexpr std::size_t kCrcBytes = 2;         // CRC16 trailer, big-endian (L699)
inline constexpr std::size_t kMaxGroupBytes = 4;    // "up to 4 group bytes" (L5359)
inline constexpr std::size_t kMaxTypeWords = 2;     // "maximum of 2 type words" per group (L5365)
inline constexpr std::uint8_t kGroupExtensionBit = 0x80;
inline constexpr std::uint16_t kTypeExtensionBit = 0x8000;
// Messages over 600 bytes in total go out as 0xFB split packets (L5397), so no valid 0xFA
// packet is longer; this bounds how long the framer waits on a candidate.
inline constexpr std::size_t kMaxBinaryPacketBytes = 600;

// The groups of this firmware (Table 2.1, L705-717), by raw group bit.
enum class Group : std::uint8_t {
  kCommon = 0,
  kTime = 1,
  kImu = 2,
  kGnss1 = 3,
  kAttitude = 4,
  kIns = 5,
  kGnss2 = 6,
  kGnss3 = 12,
};
// Dense index of a group (0..7, ascending raw bit order = payload order, L697).
inline constexpr std::size_t kGroupCount = 8;
inline constexpr std::array<Group, kGroupCount> kGroups = {Group::kCommon, Group::kTime,  Group::kImu,
                                                           Group::kGnss1,  Group::kAttitude, Group::kIns,
                                                           Group::kGnss2,  Group::kGnss3};
enum GroupSlot : std::size_t {
  kSlotCommon = 0, kSlotTime, kSlotImu, kSlotGnss1, kSlotAttitude, kSlotIns, kSlotGnss2, kSlotGnss3,
};
inline constexpr unsigned group_bit(Group g) { return static_cast<unsigned>(g); }
// Mask of every group bit this firmware defines, in the raw (concatenated-bytes) numbering.
inline constexpr std::uint32_t kKnownGroupMask = 0x107Fu;

// Type bits (raw numbering) per group: Tables 2.3, 2.4, 2.16, 2.35, 2.64, 2.75.
namespace common_type {
enum : unsigned {
  kTimeStartup = 0, kTimeGps = 1, kTimeSyncIn = 2, kYpr = 3, kQuaternion = 4, kAngularRate = 5,
  kPosLla = 6, kVelNed = 7, kAccel = 8, kImu = 9, kMagPres = 10, kDeltas = 11, kInsStatus = 12,
  kSyncInCnt = 13, kTimeGpsPps = 14,
};
}
namespace time_type {
enum : unsigned {
  kTimeStartup = 0, kTimeGps = 1, kGpsTow = 2, kGpsWeek = 3, kTimeSyncIn = 4, kTimeGpsPps = 5,
  kTimeUtc = 6, kSyncInCnt = 7, kSyncOutCnt = 8, kTimeStatus = 9,
};
}
namespace imu_type {
enum : unsigned {
  kImuStatus = 0, kUncompMag = 1, kUncompAccel = 2, kUncompGyro = 3, kTemperature = 4, kPressure = 5,
  kDeltaTheta = 6, kDeltaVel = 7, kMag = 8, kAccel = 9, kAngularRate = 10, kSensSat = 11,
};
}
namespace gnss_type {  // GNSS1, GNSS2 and GNSS3 share this table (digest §5.8)
enum : unsigned {
  kTimeUtc = 0, kGpsTow = 1, kGpsWeek = 2, kNumSats = 3, kGnssFix = 4, kPosLla = 5, kPosEcef = 6,
  kVelNed = 7, kVelEcef = 8, kPosUncertainty = 9, kVelUncertainty = 10, kTimeUncertainty = 11,
  kTimeInfo = 12, kDop = 13, kSatInfo = 14, /* 15 = extension bit */ kRawMeas = 16, kStatus = 17,
  kAltMsl = 18,
};
}
namespace attitude_type {  // bits 0 and 9-11 are unassigned in this firmware
enum : unsigned {
  kYpr = 1, kQuaternion = 2, kDcm = 3, kMagNed = 4, kAccelNed = 5, kLinBodyAcc = 6, kLinAccelNed = 7,
  kYprU = 8, kHeave = 12, kAttU = 13,
};
}
namespace ins_type {
enum : unsigned {
  kInsStatus = 0, kPosLla = 1, kPosEcef = 2, kVelBody = 3, kVelNed = 4, kVelEcef = 5, kMagEcef = 6,
  kAccelEcef = 7, kLinAccelEcef = 8, kPosU = 9, kVelU = 10,
};
}

// Variable-length GNSS types (L1321-1342, L1387-1413). Errata A17: Table 2.2's 10 and 40 are the
// one-satellite sizes; the real sizes follow these formulas.
inline constexpr std::size_t kSatInfoHeaderBytes = 2;   // Count, Resv
inline constexpr std::size_t kSatInfoEntryBytes = 8;
inline constexpr std::size_t kRawMeasHeaderBytes = 12;  // Tow, Week, NumSats, Resv
inline constexpr std::size_t kRawMeasEntryBytes = 28;
inline constexpr std::size_t kRawMeasCountOffset = 10;  // NumSats inside the RawMeas header

// Size in bytes of a fixed-size type, kVariableSize for SatInfo/RawMeas, 0 if the bit names no
// type in this firmware (such a message cannot be framed: its length is unknown).
inline constexpr std::uint8_t kVariableSize = 0xFF;
std::uint8_t type_size(std::size_t slot, unsigned type_bit);
// Mask of the type bits defined for a group slot (raw numbering, extension bits excluded).
std::uint32_t known_type_mask(std::size_t slot);
// Mask of the variable-length types of a group slot (SatInfo, RawMeas).
std::uint32_t variable_type_mask(std::size_t slot);
// Summed sizes of the fixed-size types among `types` (variable-length and undefined bits add 0).
std::size_t fixed_types_size(std::size_t slot, std::uint32_t types);
// Slot of a raw group bit, or kGroupCount if this firmware has no such group.
std::size_t slot_of_group_bit(unsigned bit);

}  // namespace navfuse::frontends::vectornav

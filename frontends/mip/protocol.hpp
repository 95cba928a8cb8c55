// MIP wire constants for the MicroStrain 3DM-CV7 (spec 001_bade83d663d26b1d.txt; digest
// reference/microstrain-mip.md). Every offset and descriptor the front-end uses is named here once.
#pragma once

#include <cstddef>
#include <cstdint>

namespace navfuse::frontends::mip {

// Packet framing (digest §2.1, spec L3814-3846): 75 65 SET LEN payload CK_MSB CK_LSB.
inline constexpr std::uint8_t kSync1 = 0x75;  // 'u'
inline constexpr std::uint8_t kSync2 = 0x65;  // 'e'
inline constexpr std::size_t kHeaderSize = 4;
inline constexpr std::size_t kChecksumSize = 2;
inline constexpr std::size_t kWrapperSize = kHeaderSize + kChecksumSize;  // "MIP wrapper = 6 bytes" (L4115)
inline constexpr std::size_t kMaxPayload = 255;                            // L3974
inline constexpr std::size_t kMaxPacket = kMaxPayload + kWrapperSize;
inline constexpr std::size_t kSetOffset = 2;
inline constexpr std::size_t kLengthOffset = 3;
// Field layout (digest §2.2, L3832-3840): LEN DESC data[LEN-2]; LEN counts itself and DESC.
inline constexpr std::size_t kFieldHeaderSize = 2;
inline constexpr std::size_t kMinFieldLength = kFieldHeaderSize;
inline constexpr std::size_t kMaxFieldData = kMaxPayload - kFieldHeaderSize;

// Descriptor sets (digest §3, L2686-2694).
namespace set {
inline constexpr std::uint8_t kBase = 0x01;
inline constexpr std::uint8_t k3dm = 0x0C;
inline constexpr std::uint8_t kFilterCmd = 0x0D;
inline constexpr std::uint8_t kGnssCmd = 0x0E;
inline constexpr std::uint8_t kAiding = 0x13;
inline constexpr std::uint8_t kSystemCmd = 0x7F;
inline constexpr std::uint8_t kSensor = 0x80;
inline constexpr std::uint8_t kFilter = 0x82;
inline constexpr std::uint8_t kGnss1 = 0x91;
inline constexpr std::uint8_t kGnss2 = 0x92;
inline constexpr std::uint8_t kGnssCorrections = 0x93;
inline constexpr std::uint8_t kGnssExternal = 0x94;
inline constexpr std::uint8_t kSystem = 0xA0;
inline constexpr std::uint8_t kShared = 0xFF;
// Command sets are 0x01..0x7F (L3850); data sets 0x80 and up.
inline constexpr bool is_command(std::uint8_t s) { return s >= 0x01 && s <= 0x7F; }
}  // namespace set

// Shared descriptors 0xD0-0xD8, valid in any data set (digest §4.5, L6565-6579).
namespace shared {
inline constexpr std::uint8_t kEventSource = 0xD0;
inline constexpr std::uint8_t kGpsTimestamp = 0xD3;
inline constexpr std::uint8_t kDeltaTime = 0xD4;
inline constexpr std::uint8_t kReferenceTimestamp = 0xD5;
inline constexpr std::uint8_t kReferenceTimeDelta = 0xD6;
inline constexpr std::uint8_t kExternalTimestamp = 0xD7;
inline constexpr std::uint8_t kExternalTimeDelta = 0xD8;
inline constexpr bool is_shared(std::uint8_t d) { return d >= kEventSource && d <= kExternalTimeDelta; }
// (0xFF,0xD3) valid_flags: bit0 tow, bit1 week; 0x0003 = time valid (L6594-6597).
inline constexpr std::uint16_t kGpsTimeValid = 0x0003;
}  // namespace shared

// Sensor set 0x80 (digest §4.1, L6360-6386).
namespace sensor {
inline constexpr std::uint8_t kScaledAccel = 0x04;
inline constexpr std::uint8_t kScaledGyro = 0x05;
inline constexpr std::uint8_t kScaledMag = 0x06;
inline constexpr std::uint8_t kDeltaTheta = 0x07;
inline constexpr std::uint8_t kDeltaVelocity = 0x08;
inline constexpr std::uint8_t kCfMatrix = 0x09;
inline constexpr std::uint8_t kCfQuaternion = 0x0A;
inline constexpr std::uint8_t kCfEuler = 0x0C;
inline constexpr std::uint8_t kGpsTimestamp = 0x12;
inline constexpr std::uint8_t kTemperature = 0x14;
inline constexpr std::uint8_t kScaledPressure = 0x17;
inline constexpr std::uint8_t kOverrange = 0x18;
inline constexpr std::uint8_t kOdometer = 0x40;
// (0x80,0x12) valid_flags bits tow_valid (3) and week_number_valid (4) (L6490-6496).
inline constexpr std::uint16_t kLegacyTimeValid = (1u << 3) | (1u << 4);
// (0x80,0x18) over-range bits (L6535-6544).
inline constexpr std::uint16_t kOverAccelX = 1u << 0, kOverAccelY = 1u << 1, kOverAccelZ = 1u << 2;
inline constexpr std::uint16_t kOverGyroX = 1u << 4, kOverGyroY = 1u << 5, kOverGyroZ = 1u << 6;
}  // namespace sensor

// Filter set 0x82 (digest §4.2, L4151-4177).
namespace filter {
inline constexpr std::uint8_t kLlh = 0x01;
inline constexpr std::uint8_t kVelNed = 0x02;
inline constexpr std::uint8_t kQuaternion = 0x03;
inline constexpr std::uint8_t kDcm = 0x04;
inline constexpr std::uint8_t kEuler = 0x05;
inline constexpr std::uint8_t kGyroBias = 0x06;
inline constexpr std::uint8_t kAccelBias = 0x07;
inline constexpr std::uint8_t kLlhUnc = 0x08;
inline constexpr std::uint8_t kVelUnc = 0x09;
inline constexpr std::uint8_t kEulerUnc = 0x0A;
inline constexpr std::uint8_t kGyroBiasUnc = 0x0B;
inline constexpr std::uint8_t kAccelBiasUnc = 0x0C;
inline constexpr std::uint8_t kLinearAccel = 0x0D;
inline constexpr std::uint8_t kCompAngularRate = 0x0E;
inline constexpr std::uint8_t kStatus = 0x10;
inline constexpr std::uint8_t kTimestamp = 0x11;
inline constexpr std::uint8_t kQuaternionUnc = 0x12;
inline constexpr std::uint8_t kGravity = 0x13;
inline constexpr std::uint8_t kAntennaOffsetCorrection = 0x34;     // multi-antenna, L4497
inline constexpr std::uint8_t kAntennaOffsetCorrectionUnc = 0x35;  // L4512
inline constexpr std::uint8_t kOdometerScaleError = 0x47;          // L4654
inline constexpr std::uint8_t kOdometerScaleErrorUnc = 0x48;       // L4667
inline constexpr std::uint8_t kDualAntennaStatus = 0x49;
// Filter states (0x82,0x10), CV7/GQ7 values (L4370-4379; errata E36: ignore the GX5 values).
inline constexpr std::uint16_t kStateInit = 1, kStateVerticalGyro = 2, kStateAhrs = 3, kStateFullNav = 4;
inline constexpr std::uint16_t kDynamicsDefault = 1;  // GQ7_DEFAULT (L4385)
// Status flags (digest §6.3, L656-706).
inline constexpr std::uint16_t kConditionMask = 0x0003;
inline constexpr std::uint16_t kConditionStable = 1, kConditionConverging = 2, kConditionUnstable = 3;
inline constexpr std::uint16_t kFlagRollPitchWarning = 1u << 2;
inline constexpr std::uint16_t kFlagHeadingWarning = 1u << 3;
inline constexpr std::uint16_t kFlagPositionWarning = 1u << 4;
inline constexpr std::uint16_t kFlagVelocityWarning = 1u << 5;
inline constexpr std::uint16_t kFlagImuBiasWarning = 1u << 6;
inline constexpr std::uint16_t kFlagTimeSyncWarning = 1u << 10;
inline constexpr std::uint16_t kFlagSolutionError = 0xF000;  // bits 12-15 (errata E16: any set)
inline constexpr std::uint16_t kValid = 1;  // 0x82 valid_flags: 0 invalid, 1 valid (L4191)
// (0x82,0x49) fix types (L4679).
inline constexpr std::uint8_t kDaFixNone = 0, kDaFixFloat = 1, kDaFixFixed = 2;
}  // namespace filter

// GNSS sets 0x91/0x92/0x94 (digest §4.3, L4979-5668).
namespace gnss {
inline constexpr std::uint8_t kLlh = 0x03;
inline constexpr std::uint8_t kEcefPos = 0x04;
inline constexpr std::uint8_t kVelNed = 0x05;
inline constexpr std::uint8_t kEcefVel = 0x06;
inline constexpr std::uint8_t kDop = 0x07;
inline constexpr std::uint8_t kUtcTime = 0x08;
inline constexpr std::uint8_t kGpsTime = 0x09;
inline constexpr std::uint8_t kFixInfo = 0x0B;
// (0x9x,0x03) valid flags (L4985).
inline constexpr std::uint16_t kLlhValidLatLon = 1u << 0, kLlhValidHeight = 1u << 1, kLlhValidMsl = 1u << 2;
inline constexpr std::uint16_t kLlhValidHAcc = 1u << 3, kLlhValidVAcc = 1u << 4;
// (0x9x,0x05) valid flags (L5032).
inline constexpr std::uint16_t kVelValidNed = 1u << 0, kVelValidSpeedAcc = 1u << 4;
// (0x9x,0x09) valid flags: bit0 tow, bit1 week (L5136).
inline constexpr std::uint16_t kGpsTimeValid = 0x0003;
// (0x9x,0x0B) fix types and flags (L5156).
inline constexpr std::uint8_t kFix3d = 0, kFix2d = 1, kFixTimeOnly = 2, kFixNone = 3, kFixInvalid = 4;
inline constexpr std::uint8_t kFixRtkFloat = 5, kFixRtkFixed = 6, kFixDifferential = 7;
inline constexpr std::uint16_t kFixFlagSbas = 1u << 0, kFixFlagDgnss = 1u << 1;
inline constexpr std::uint16_t kFixValidType = 1u << 0, kFixValidNumSv = 1u << 1, kFixValidFlags = 1u << 2;
}  // namespace gnss

// Command-set descriptors used by name in code (full tables in command_schema.cpp).
inline constexpr std::uint8_t kAckNackDescriptor = 0xF1;  // L8862-8881, reserved in every command set
inline constexpr std::size_t kAckFieldLength = 4;

// ACK/NACK reply codes (digest §2.5, L8873-8881).
enum class ReplyCode : std::uint8_t {
  kAck = 0x00,
  kUnknownCommand = 0x01,
  kBadChecksum = 0x02,
  kInvalidParameter = 0x03,
  kCommandFailed = 0x04,
  kTimeout = 0x05,
  kUnknownDescriptorSet = 0x06,
};

// Function selectors (digest §2.6, L8883-8890; errata E33: 0x05 default).
enum class Function : std::uint8_t { kWrite = 1, kRead = 2, kSave = 3, kLoad = 4, kDefault = 5 };

}  // namespace navfuse::frontends::mip

// Field layouts of the registers a VN-300 prints in ASCII: the asynchronous outputs of Reg 6
// (ADOR, digest §2.6) and the register read/write replies (ICD §3-4, digest §6). An async
// sentence `$VN<HDR>,...` has the same fields in the same order as `$VNRRG,<id>,...` (L143-145);
// SPI-only -PAD- fields never appear in ASCII.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace navfuse::frontends::vectornav {

// Register ids used by name elsewhere (register index, ICD p.178, L5418-5457).
namespace reg {
inline constexpr int kBaudRate = 5, kAsyncType = 6, kAsyncFreq = 7, kYpr = 8, kQuaternion = 9;
inline constexpr int kQuatMagAccelGyro = 15, kMag = 17, kAccel = 18, kGyro = 19, kMagAccelGyro = 20;
inline constexpr int kReferenceFrameRotation = 26, kYprMagAccelGyro = 27, kCommProtocol = 30;
inline constexpr int kVelAidMeasurement = 50, kVelAidControl = 51, kImuMeasurements = 54;
inline constexpr int kGnssAntennaA = 57, kGnssLla = 58, kGnssEcef = 59, kInsLla = 63, kInsEcef = 64;
inline constexpr int kInsBasicConfig = 67, kInsStateLla = 72, kInsStateEcef = 73;
inline constexpr int kBinaryOutput1 = 75, kBinaryOutput2 = 76, kBinaryOutput3 = 77;
inline constexpr int kDeltaThetaVel = 80, kDeltaConfig = 82, kImuFilter = 85, kCompassBaseline = 93;
inline constexpr int kCompassStartup = 98, kGnss2Lla = 103, kGnss2Ecef = 104, kHeave = 115;
inline constexpr int kExternalGnssAntenna = 157, kYprLinBodyGyro = 239, kYprLinNedGyro = 240;
}  // namespace reg

struct RegisterLayout {
  int id = 0;
  std::string_view async_header;  // "VNYPR"..., empty if the register is not an async output
  std::span<const std::string_view> fields;  // names with units, in ASCII order
  std::uint32_t hex_fields = 0;   // bit i: field i is printed as hex (InsStatus, Reg 75 words)
};

// Layout of a register by id, or by async header; nullptr when unknown.
const RegisterLayout* find_register(int id);
const RegisterLayout* find_async_output(std::string_view header);

}  // namespace navfuse::frontends::vectornav

// FusionEngine wire basics shared by every message: the 24-byte header, the Timestamp and
// MeasurementDetails structs, InterfaceID, message type ids and the enumerations the fusion
// front-end maps to core types.
//
// Source: Point One "FusionEngine Message Specification" v0.24 (specs/000_fdbfb707714ca8e1.txt),
// digest reference/fusionengine.md. All payloads are little endian (spec §2.2 L175) and packed
// without implicit padding (digest §1.1), so everything is read byte by byte, never by casting.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>

namespace navfuse::frontends::fusionengine {

// ---------------------------------------------------------------------------------------------
// Header (spec §2.3 L179-193, digest §1.3).
inline constexpr std::uint8_t kSync0 = 0x2E;  // '.'
inline constexpr std::uint8_t kSync1 = 0x31;  // '1'
inline constexpr std::size_t kHeaderSize = 24;
inline constexpr std::size_t kCrcOffset = 4;
// The CRC covers everything from the protocol version byte to the end of the payload (L186).
inline constexpr std::size_t kCrcCoveredFrom = 8;
inline constexpr std::size_t kProtocolVersionOffset = 8;
inline constexpr std::size_t kMessageVersionOffset = 9;
inline constexpr std::size_t kMessageTypeOffset = 10;
inline constexpr std::size_t kSequenceOffset = 12;
inline constexpr std::size_t kPayloadSizeOffset = 16;
inline constexpr std::size_t kSourceIdOffset = 20;
// "Currently set to 2 always" (L188). SSRStatus claims 3 (L2494, digest §13 A13); the framer
// does not reject on this byte, the writer always writes 2.
inline constexpr std::uint8_t kProtocolVersion = 2;
// The spec gives no maximum payload (digest §1.5); the public client uses 1 << 24. Longer
// lengths are treated as corrupt headers so that one flipped bit cannot stall the stream.
inline constexpr std::uint32_t kMaxPayloadSize = 1u << 24;
// Bytes navfuse never interprets, whose size neither the spec nor a count field bounds below
// kMaxPayloadSize: the data of ImportData / PlatformStorageData (u32 Data Length, L1381-1398,
// L1625-1651), the bytes InputDataWrapper wraps (L2445-2463) and STA5635 IQ samples
// (L2870-2886), all "the rest" or "Variable" in the spec. They are only skipped, answered or
// dumped as hex, so a genuine longer one costs its bytes being counted as skipped (as for a type
// the catalogue does not know, message_catalog.hpp), while a corrupted size claiming 16 MiB
// would cost a wait for, and a CRC over, 16 MiB. 64 KiB holds one whole frame of the native
// formats a device wraps (RTCM 3 at most 1029 bytes; upstream drivers unwrap one Septentrio SBF
// block per wrapper, whose length is a u16) and is 256x the largest config value.
inline constexpr std::uint32_t kMaxOpaqueDataSize = 64 * 1024;
// Source Identifier: "Typically set to 0 for measurement input messages, or 0xFFFFFFFF (invalid)
// for non-measurement messages" (L193). Decoders never validate it (digest §13 A14).
inline constexpr std::uint32_t kSourceIdMeasurementInput = 0;
inline constexpr std::uint32_t kSourceIdInvalid = 0xFFFFFFFFu;

struct Header {
  std::uint32_t crc = 0;
  std::uint8_t protocol_version = kProtocolVersion;
  std::uint8_t message_version = 0;
  std::uint16_t message_type = 0;
  std::uint32_t sequence = 0;
  std::uint32_t payload_size = 0;
  std::uint32_t source_id = kSourceIdInvalid;
};

// ---------------------------------------------------------------------------------------------
// Message type ids (spec chapter 3, digest §3 catalogue).
enum class MessageType : std::uint16_t {
  kPose = 10000,
  kGnssInfo = 10001,
  kGnssSatellite = 10002,
  kPoseAux = 10003,
  kCalibrationStatus = 10004,
  kRelativeEnuPosition = 10005,
  kGnssSignals = 10006,
  kSystemStatus = 10500,
  kSsrStatus = 10501,
  kImuOutput = 11000,
  kRawImuOutput = 11002,
  kImuInput = 11004,
  kGnssAttitudeOutput = 11005,
  kRawGnssAttitudeOutput = 11006,
  kWheelTickInput = 11103,
  kVehicleTickInput = 11104,
  kWheelSpeedInput = 11105,
  kVehicleSpeedInput = 11106,
  kRawWheelTickOutput = 11123,
  kRawVehicleTickOutput = 11124,
  kRawWheelSpeedOutput = 11125,
  kRawVehicleSpeedOutput = 11126,
  kWheelSpeedOutput = 11135,
  kVehicleSpeedOutput = 11136,
  kRosPose = 12000,
  kRosGpsFix = 12010,
  kRosImu = 12011,
  kCommandResponse = 13000,
  kMessageRequest = 13001,
  kResetRequest = 13002,
  kVersionInfo = 13003,
  kEventNotification = 13004,
  kShutdownRequest = 13005,
  kFaultControl = 13006,
  kDeviceId = 13007,
  kStartupRequest = 13008,
  kSetConfig = 13100,
  kGetConfig = 13101,
  kSaveConfig = 13102,
  kConfigResponse = 13103,
  kImportData = 13110,
  kExportData = 13111,
  kPlatformStorageData = 13113,
  kInputDataWrapper = 13120,
  kSetMessageRate = 13220,
  kGetMessageRate = 13221,
  kMessageRateResponse = 13222,
  kSupportedIoInterfaces = 13223,
  kLBandFrame = 14000,
  kSta5635Command = 14100,
  kSta5635CommandResponse = 14101,
  kSta5635IqData = 14102,
};
inline constexpr std::uint16_t to_u16(MessageType t) { return static_cast<std::uint16_t>(t); }

// ---------------------------------------------------------------------------------------------
// Floats have no stated invalid value in most messages; NaN is the convention where one is
// stated (wheel speed outputs L2111-2114, Pose body velocity L1752, digest §2.6).
inline constexpr float kNanF = std::numeric_limits<float>::quiet_NaN();
inline constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Timestamp (spec §2.6.1 L249-257): whole seconds + nanoseconds, each 0xFFFFFFFF when invalid.
inline constexpr std::uint32_t kInvalidU32 = 0xFFFFFFFFu;
struct Timestamp {
  std::uint32_t seconds = kInvalidU32;
  std::uint32_t fraction_ns = kInvalidU32;
  bool valid() const { return seconds != kInvalidU32 && fraction_ns != kInvalidU32; }
  std::int64_t ns() const {
    return static_cast<std::int64_t>(seconds) * 1'000'000'000 + static_cast<std::int64_t>(fraction_ns);
  }
  // Invalid for negative or out-of-range times (a u32 of seconds covers 136 years).
  static Timestamp from_ns(std::int64_t ns);
};
inline Timestamp Timestamp::from_ns(std::int64_t ns) {
  constexpr std::int64_t kNs = 1'000'000'000;
  if (ns < 0 || ns / kNs >= static_cast<std::int64_t>(kInvalidU32)) return {};
  return {static_cast<std::uint32_t>(ns / kNs), static_cast<std::uint32_t>(ns % kNs)};
}

// SystemTimeSource (spec §2.6.2 L261-273).
enum class SystemTimeSource : std::uint8_t {
  kInvalid = 0,
  kP1Time = 1,
  kTimestampedOnReception = 2,
  kSenderSystemTime = 3,
  kGpsTime = 4,
};
// SensorDataSource (spec §2.6.3 L277-290).
enum class SensorDataSource : std::uint8_t {
  kUnknown = 0, kInternal = 1, kHardwareIo = 2, kCan = 3, kSerial = 4, kNetwork = 5,
};

// MeasurementDetails (spec §2.6.4 L294-311): 20 bytes at the start of every sensor input and
// raw output message.
struct MeasurementDetails {
  static constexpr std::size_t kSize = 20;
  Timestamp measurement_time;
  std::uint8_t time_source = 0;  // SystemTimeSource
  std::uint8_t sensor_source = 0;  // SensorDataSource
  // "Leave invalid when sending measurements to the device" (L298-302).
  Timestamp p1_time;
  template <class V>
  void visit(V& v) {
    v.timestamp("meas_time", measurement_time);
    v.field("time_source", time_source);
    v.field("sensor_source", sensor_source);
    v.reserved(2);
    v.timestamp("p1_time", p1_time);
  }
};

// InterfaceID (spec §2.6.7 L576-602): transport type, index, 2 reserved bytes.
enum class TransportType : std::uint8_t {
  kInvalid = 0, kSerial = 1, kFile = 2,
  // Spec L595 says TCP = 3 and 4 reserved; upstream v1.25.0 has TCP = 4 (digest §13 A6).
  kTcpSpec = 3, kTcpUpstream = 4,
  kUdp = 5, kWebSocket = 7, kUnixSocket = 8, kCurrent = 0xFE, kAll = 0xFF,
};
struct InterfaceId {
  static constexpr std::size_t kSize = 4;
  std::uint8_t type = 0;  // TransportType
  std::uint8_t index = 0;
  template <class V>
  void visit(V& v) {
    v.field("iface_type", type);
    v.field("iface_index", index);
    v.reserved(2);
  }
};

// ---------------------------------------------------------------------------------------------
// Enumerations the fusion mapping needs.

// SolutionType (spec L1764-1778).
enum class SolutionType : std::uint8_t {
  kInvalid = 0, kAutonomousGps = 1, kDgps = 2, kRtkFixed = 4, kRtkFloat = 5, kIntegrate = 6,
  kVisual = 9, kPpp = 10,
};
// GearType (spec §2.6.6 L560-572): the same values as navfuse::Gear.
enum class GearType : std::uint8_t { kUnknown = 0, kForward = 1, kReverse = 2, kPark = 3, kNeutral = 4 };

// Response codes (spec §3.2.1 L1579-1590).
enum class Response : std::uint8_t {
  kOk = 0,
  kUnsupportedMessageVersion = 1,
  kUnsupportedFeature = 2,
  kValueError = 3,
  kInsufficientSpace = 4,
  kExecutionFailure = 5,
  kInconsistentPayloadLength = 6,
  kDataCorrupted = 7,
  kNoDataStored = 8,
  kUnavailable = 9,
  kUnsupportedInterface = 10,
};

}  // namespace navfuse::frontends::fusionengine

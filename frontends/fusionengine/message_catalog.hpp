// The catalogue of every message the spec defines (digest §3: 52 messages), as one type list,
// and a holder with one instance of each that decoders reuse frame after frame (variable-length
// messages keep their vectors' capacity, so steady-state decoding does not allocate).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <tuple>

#include "frontends/fusionengine/messages_control.hpp"
#include "frontends/fusionengine/messages_ros.hpp"
#include "frontends/fusionengine/messages_sensor.hpp"
#include "frontends/fusionengine/messages_solution.hpp"
#include "frontends/fusionengine/messages_status.hpp"

namespace navfuse::frontends::fusionengine {

using AllMessages = std::tuple<
    PoseMessage, GnssInfoMessage, GnssSatelliteMessage, PoseAuxMessage, CalibrationStatusMessage,
    RelativeEnuPositionMessage, GnssSignalsMessage, SystemStatusMessage, SsrStatusMessage,
    ImuOutputMessage, RawImuOutputMessage, ImuInputMessage, GnssAttitudeOutputMessage,
    RawGnssAttitudeOutputMessage, WheelTickInputMessage, VehicleTickInputMessage,
    WheelSpeedInputMessage, VehicleSpeedInputMessage, RawWheelTickOutputMessage,
    RawVehicleTickOutputMessage, RawWheelSpeedOutputMessage, RawVehicleSpeedOutputMessage,
    WheelSpeedOutputMessage, VehicleSpeedOutputMessage, RosPoseMessage, RosGpsFixMessage,
    RosImuMessage, CommandResponseMessage, MessageRequestMessage, ResetRequestMessage,
    VersionInfoMessage, EventNotificationMessage, ShutdownRequestMessage, FaultControlMessage,
    DeviceIdMessage, StartupRequestMessage, SetConfigMessage, GetConfigMessage, SaveConfigMessage,
    ConfigResponseMessage, ImportDataMessage, ExportDataMessage, PlatformStorageDataMessage,
    InputDataWrapperMessage, SetMessageRateMessage, GetMessageRateMessage,
    MessageRateResponseMessage, SupportedIoInterfacesMessage, LBandFrameMessage,
    Sta5635CommandMessage, Sta5635CommandResponseMessage, Sta5635IqDataMessage>;

inline constexpr std::size_t kCatalogSize = std::tuple_size_v<AllMessages>;

// Payload sizes a frame header may claim before the framer treats it as corrupt: for a type of
// the catalogue, the largest payload its layout can express (payload_bound(), payload_bound.hpp:
// the fixed part plus what its count and length fields can express, or its documented
// kMaxVariableSize) plus kMaxVersionGrowth, since a newer version may extend any message ("extending
// the message length", spec L189); for a type the catalogue does not know, kMaxUnknownPayloadSize.
// Without these bounds one corrupted size byte, in an IMU frame or a GNSSSignals frame, or a
// corrupted header naming an unknown type, makes the framer wait for, and CRC, up to 16 MiB
// before it can resynchronise (issue 15.11). An unknown type is never decoded, only skipped, so a
// genuine one beyond the bound costs nothing but its bytes being counted as skipped instead of as
// an unknown frame (kMaxOpaqueDataSize, wire.hpp, says the same of the opaque known ones).
inline constexpr std::uint32_t kMaxVersionGrowth = 4096;
inline constexpr std::uint32_t kMaxUnknownPayloadSize = kMaxOpaqueDataSize;
std::uint32_t max_payload_size(std::uint16_t message_type);

// The spec's name of a message type ("Pose", "IMUOutput", ...), or nullopt for an id the spec
// does not define.
std::optional<std::string_view> message_name(std::uint16_t message_type);

// Calls f(msg) with the reused instance of the message type `message_type`; returns false when
// the type is not in the catalogue.
class MessageSet {
 public:
  template <class F>
  bool dispatch(std::uint16_t message_type, F&& f) {
    // The two hot types first: they are most of every real stream.
    if (message_type == to_u16(PoseMessage::kType)) return f(std::get<PoseMessage>(all_)), true;
    if (message_type == to_u16(ImuOutputMessage::kType)) return f(std::get<ImuOutputMessage>(all_)), true;
    return std::apply(
        [&](auto&... m) {
          return ((to_u16(std::decay_t<decltype(m)>::kType) == message_type ? (f(m), true) : false) || ...);
        },
        all_);
  }

 private:
  AllMessages all_;
};

}  // namespace navfuse::frontends::fusionengine

// SetConfig / ConfigResponse parameter types and their value layouts (spec §3.1.6 L939-1305,
// digest §7.6), with helpers that pack a typed value into the bytes a SetConfig carries and
// parse it back.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "frontends/fusionengine/payload_reader.hpp"
#include "frontends/fusionengine/payload_writer.hpp"

namespace navfuse::frontends::fusionengine {

// ConfigType (u16), spec L963-1003.
enum class ConfigType : std::uint16_t {
  kInvalid = 0x0,
  kDeviceLeverArm = 0x10,
  kDeviceCoarseOrientation = 0x11,
  kGnssLeverArm = 0x12,
  kOutputLeverArm = 0x13,
  kVehicleDetails = 0x14,
  kWheelConfig = 0x15,
  kHardwareTickConfig = 0x16,
  kHeadingBias = 0x17,  // deprecated in 1.24.0 for kGnssAuxLeverArm (L978)
  kGnssAuxLeverArm = 0x18,
  kEnabledGnssSystems = 0x32,
  kEnabledGnssFrequencyBands = 0x33,
  kLeapSecond = 0x34,
  kGpsWeekRollover = 0x35,
  kIonosphereConfig = 0x36,
  kTroposphereConfig = 0x37,
  kInterfaceConfig = 0xC8,
  kUart1BaudRate = 0x100,
  kUart2BaudRate = 0x101,
  kUart1OutputDiagnostics = 0x102,
  kUart2OutputDiagnostics = 0x103,
  kEnableWatchdogTimer = 0x12C,
  kUserDeviceId = 0x12D,
  kProfilingMask = 0x136,
  kLBandParameters = 0x400,
};
inline constexpr std::uint16_t to_u16(ConfigType t) { return static_cast<std::uint16_t>(t); }
std::string_view to_string(ConfigType t);

// Point3f (L1039-1044): a body-frame (FLU) vector in metres, used by every lever arm.
struct Point3f {
  static constexpr std::size_t kSize = 12;
  std::array<float, 3> xyz_m{};
  template <class V>
  void visit(V& v) {
    v.field("x_m", xyz_m[0]);
    v.field("y_m", xyz_m[1]);
    v.field("z_m", xyz_m[2]);
  }
};

// navfuse config lever arms are vehicle FRD, FusionEngine's Point3f FLU body (spec L635-653,
// L1039-1044): y and z change sign.
Point3f point_from_frd(const std::array<double, 3>& frd_m);
std::array<double, 3> frd_from_point(const Point3f& p);

// CoarseOrientation (L1046-1067): directions of the IMU +X and +Z axes in the vehicle body.
enum class Direction : std::uint8_t {
  kForward = 0, kBackward = 1, kLeft = 2, kRight = 3, kUp = 4, kDown = 5, kInvalid = 0xFF,
};
struct CoarseOrientation {
  static constexpr std::size_t kSize = 4;
  std::uint8_t x_direction = static_cast<std::uint8_t>(Direction::kForward);
  std::uint8_t z_direction = static_cast<std::uint8_t>(Direction::kUp);
  template <class V>
  void visit(V& v) {
    v.field("x_direction", x_direction);
    v.field("z_direction", z_direction);
    v.reserved(2);
  }
};

// VehicleDetails (L1069-1109), 24 bytes.
struct VehicleDetails {
  static constexpr std::size_t kSize = 24;
  std::uint16_t vehicle_model = 0;
  float wheelbase_m = 0;
  float front_track_width_m = 0;
  float rear_track_width_m = 0;
  template <class V>
  void visit(V& v) {
    v.field("vehicle_model", vehicle_model);
    v.reserved(10);
    v.field("wheelbase_m", wheelbase_m);
    v.field("front_track_width_m", front_track_width_m);
    v.field("rear_track_width_m", rear_track_width_m);
  }
};

// WheelConfig (L1111-1172), 28 bytes: software wheel speed / tick configuration.
enum class WheelSensorType : std::uint8_t {
  kNone = 0, kTicks = 2, kWheelSpeed = 3, kVehicleSpeed = 4, kVehicleTicks = 5,
};
enum class AppliedSpeedType : std::uint8_t {
  kNone = 0, kRearWheels = 1, kFrontWheels = 2, kFrontAndRearWheels = 3, kVehicleBody = 4,
};
enum class SteeringType : std::uint8_t { kUnknown = 0, kFront = 1, kFrontAndRear = 2 };
struct WheelConfig {
  static constexpr std::size_t kSize = 28;
  std::uint8_t wheel_sensor_type = 0;   // WheelSensorType
  std::uint8_t applied_speed_type = 1;  // AppliedSpeedType; REAR_WHEELS "recommended" (L1125)
  std::uint8_t steering_type = 0;       // SteeringType
  float wheel_update_interval_s = 0;
  float wheel_tick_output_interval_s = 0;
  float steering_ratio = 0;
  float wheel_ticks_to_m = 0;        // metres per tick (L1147, digest §13 B18)
  std::uint32_t wheel_tick_max_value = 0;  // rollover value (L1134)
  std::uint8_t wheel_ticks_signed = 0;
  std::uint8_t wheel_ticks_always_increase = 0;
  template <class V>
  void visit(V& v) {
    v.field("wheel_sensor_type", wheel_sensor_type);
    v.field("applied_speed_type", applied_speed_type);
    v.field("steering_type", steering_type);
    v.reserved(1);
    v.field("wheel_update_interval_s", wheel_update_interval_s);
    v.field("wheel_tick_output_interval_s", wheel_tick_output_interval_s);
    v.field("steering_ratio", steering_ratio);
    v.field("wheel_ticks_to_m", wheel_ticks_to_m);
    v.field("wheel_tick_max_value", wheel_tick_max_value);
    v.field("wheel_ticks_signed", wheel_ticks_signed);
    v.field("wheel_ticks_always_increase", wheel_ticks_always_increase);
    v.reserved(2);
  }
};

// HardwareTickConfig (L1177-1207). The spec's single reserved byte would put the f32 at
// offset 3; upstream has two, giving 8 bytes with the f32 at offset 4 (digest §13 A3).
struct HardwareTickConfig {
  static constexpr std::size_t kSize = 8;
  std::uint8_t tick_mode = 0;
  std::uint8_t tick_direction = 0;
  float wheel_ticks_to_m = 0;
  template <class V>
  void visit(V& v) {
    v.field("tick_mode", tick_mode);
    v.field("tick_direction", tick_direction);
    v.reserved(2);
    v.field("wheel_ticks_to_m", wheel_ticks_to_m);
  }
};

// Single-value config payloads (u32 masks / baud rates, i32 overrides, bool/u8 switches).
template <typename T>
struct ScalarConfig {
  static constexpr std::size_t kSize = sizeof(T);
  T value{};
  template <class V>
  void visit(V& v) {
    v.field("value", value);
  }
};
// Ionosphere / troposphere model (L1262-1290): one u8 model and 3 reserved bytes.
struct DelayModelConfig {
  static constexpr std::size_t kSize = 4;
  std::uint8_t model = 0;
  template <class V>
  void visit(V& v) {
    v.field("model", model);
    v.reserved(3);
  }
};

// The value bytes of a typed config (the `Value` field of SetConfig / ConfigResponse).
template <class C>
std::vector<std::uint8_t> pack_config(C value) {
  std::vector<std::uint8_t> out;
  out.reserve(C::kSize);
  PayloadWriter w(out);
  value.visit(w);
  return out;
}
// Parses a typed config value; nullopt when `bytes` is shorter than the type.
template <class C>
std::optional<C> parse_config(std::span<const std::uint8_t> bytes) {
  C value;
  PayloadReader r(bytes);
  value.visit(r);
  if (!r.ok()) return std::nullopt;
  return value;
}

// Value size the spec defines for a config type, or 0 when unknown / variable.
constexpr std::size_t config_value_size(std::uint16_t config_type) {
  switch (static_cast<ConfigType>(config_type)) {
    case ConfigType::kDeviceLeverArm:
    case ConfigType::kGnssLeverArm:
    case ConfigType::kOutputLeverArm:
    case ConfigType::kGnssAuxLeverArm:
      return Point3f::kSize;
    case ConfigType::kDeviceCoarseOrientation: return CoarseOrientation::kSize;
    case ConfigType::kVehicleDetails: return VehicleDetails::kSize;
    case ConfigType::kWheelConfig: return WheelConfig::kSize;
    case ConfigType::kHardwareTickConfig: return HardwareTickConfig::kSize;
    case ConfigType::kEnabledGnssSystems:
    case ConfigType::kEnabledGnssFrequencyBands:
    case ConfigType::kLeapSecond:
    case ConfigType::kGpsWeekRollover:
    case ConfigType::kUart1BaudRate:
    case ConfigType::kUart2BaudRate:
      return 4;
    case ConfigType::kIonosphereConfig:
    case ConfigType::kTroposphereConfig:
      return DelayModelConfig::kSize;
    case ConfigType::kUart1OutputDiagnostics:
    case ConfigType::kUart2OutputDiagnostics:
    case ConfigType::kEnableWatchdogTimer:
    case ConfigType::kProfilingMask:
      return 1;
    case ConfigType::kUserDeviceId: return 32;  // char[32] (L996)
    case ConfigType::kLBandParameters: return 28;  // LBandConfig (L1293-1305)
    default: return 0;
  }
}

// InterfaceConfigSubmessage (L1211-1254): an InterfaceID, the InterfaceConfigType u8 and 3
// reserved bytes, then a value whose largest form is REMOTE_ADDRESS, char[64] (L1228).
inline constexpr std::size_t kInterfaceConfigHeaderSize = InterfaceId::kSize + 4;
inline constexpr std::size_t kMaxInterfaceConfigValueSize = 64;

// The largest config value the spec defines (the Value of SetConfig / ConfigResponse, whose u32
// Value Length could claim 4 GiB): every type up to the last defined one, 0x400 (types above
// are reserved, L1003), and the variable-length InterfaceConfig.
constexpr std::size_t max_config_value_size() {
  std::size_t n = kInterfaceConfigHeaderSize + kMaxInterfaceConfigValueSize;
  for (std::uint32_t t = 0; t <= to_u16(ConfigType::kLBandParameters); ++t) {
    const std::size_t s = config_value_size(static_cast<std::uint16_t>(t));
    if (s > n) n = s;
  }
  return n;
}
inline constexpr std::size_t kMaxConfigValueSize = max_config_value_size();

}  // namespace navfuse::frontends::fusionengine

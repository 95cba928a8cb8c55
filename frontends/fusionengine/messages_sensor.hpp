// Sensor messages (spec §3.4-3.6, digest §6): corrected outputs, inputs and raw outputs of IMU,
// dual-antenna GNSS attitude and wheel / vehicle speed and ticks, plus InputDataWrapper.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

// Scaled-integer sentinels and scale factors. The spec writes "2e-7", "2e-16", "2e-20" and
// "2e-10" in places (L2187-2193, L2404-2407, L2432) next to 2^-n elsewhere; they are 2^-n
// (digest §13 A9).
inline constexpr std::int32_t kInvalidI32 = 0x7FFFFFFF;
inline constexpr std::int16_t kInvalidTemperature = 0x7FFF;
inline constexpr double kTemperatureLsbDegC = 1.0 / 128.0;        // 2^-7  (L2312)
inline constexpr double kAccelLsbMps2 = 1.0 / 65536.0;             // 2^-16 (L2313-2315)
inline constexpr double kGyroLsbRps = 1.0 / 1048576.0;             // 2^-20 (L2316-2318)
inline constexpr double kWheelSpeedLsbMps = 1.0 / 1024.0;          // 2^-10 (L2248-2251)
inline constexpr std::uint8_t kSpeedFlagSigned = 0x01;             // L2253, L2280, L2117

// IMUOutput 11000, 104 bytes (spec §3.4.1 L2029-2054): corrected, vehicle body (FLU) frame.
struct ImuOutputMessage {
  static constexpr MessageType kType = MessageType::kImuOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "IMUOutput";
  static constexpr std::size_t kSize = 104;
  Timestamp p1_time;
  std::array<double, 3> accel_mps2{};
  std::array<double, 3> accel_std_mps2{};
  std::array<double, 3> gyro_rps{};
  std::array<double, 3> gyro_std_rps{};
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.field("accel_x_mps2", accel_mps2[0]);
    v.field("accel_y_mps2", accel_mps2[1]);
    v.field("accel_z_mps2", accel_mps2[2]);
    v.field("accel_std_x_mps2", accel_std_mps2[0]);
    v.field("accel_std_y_mps2", accel_std_mps2[1]);
    v.field("accel_std_z_mps2", accel_std_mps2[2]);
    v.field("gyro_x_rps", gyro_rps[0]);
    v.field("gyro_y_rps", gyro_rps[1]);
    v.field("gyro_z_rps", gyro_rps[2]);
    v.field("gyro_std_x_rps", gyro_std_rps[0]);
    v.field("gyro_std_y_rps", gyro_std_rps[1]);
    v.field("gyro_std_z_rps", gyro_std_rps[2]);
  }
};

// IMUInput 11004 and RawIMUOutput 11002 share one 52-byte layout (spec §3.5.1 L2174-2193,
// §3.6.1 L2297-2318): sensor-frame scaled integers.
struct ScaledImuLayout {
  static constexpr std::size_t kSize = 52;
  MeasurementDetails details;
  std::int16_t temperature = kInvalidTemperature;  // deg C * 2^7
  std::array<std::int32_t, 3> accel{kInvalidI32, kInvalidI32, kInvalidI32};  // m/s^2 * 2^16
  std::array<std::int32_t, 3> gyro{kInvalidI32, kInvalidI32, kInvalidI32};   // rad/s * 2^20
  template <class V>
  void visit(V& v) {
    details.visit(v);
    v.reserved(6);
    v.field("temperature_2^-7degc", temperature);
    v.field("accel_x_2^-16mps2", accel[0]);
    v.field("accel_y_2^-16mps2", accel[1]);
    v.field("accel_z_2^-16mps2", accel[2]);
    v.field("gyro_x_2^-20rps", gyro[0]);
    v.field("gyro_y_2^-20rps", gyro[1]);
    v.field("gyro_z_2^-20rps", gyro[2]);
  }
};
struct ImuInputMessage : ScaledImuLayout {
  static constexpr MessageType kType = MessageType::kImuInput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "IMUInput";
};
struct RawImuOutputMessage : ScaledImuLayout {
  static constexpr MessageType kType = MessageType::kRawImuOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "RawIMUOutput";
};

// GNSSAttitudeOutput 11005 (spec §3.4.2 L2058-2088). The spec's Flags is u8, which would put
// every float at an odd offset (57 bytes); the u32 of RawGNSSAttitudeOutput and upstream is
// used instead, 60 bytes (digest §13 A2).
struct GnssAttitudeOutputMessage {
  static constexpr MessageType kType = MessageType::kGnssAttitudeOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "GNSSAttitudeOutput";
  static constexpr std::size_t kSize = 60;
  MeasurementDetails details;
  std::uint8_t solution_type = 0;  // Invalid: no heading; RTKFixed: heading available (L2072)
  std::uint32_t flags = 0;
  std::array<float, 3> ypr_deg{};
  std::array<float, 3> ypr_std_deg{};
  float baseline_distance_m = 0;
  float baseline_distance_std_m = 0;
  template <class V>
  void visit(V& v) {
    details.visit(v);
    v.field("solution_type", solution_type);
    v.reserved(3);
    v.field("flags", flags);
    v.field("yaw_deg", ypr_deg[0]);
    v.field("pitch_deg", ypr_deg[1]);
    v.field("roll_deg", ypr_deg[2]);
    v.field("yaw_std_deg", ypr_std_deg[0]);
    v.field("pitch_std_deg", ypr_std_deg[1]);
    v.field("roll_std_deg", ypr_std_deg[2]);
    v.field("baseline_m", baseline_distance_m);
    v.field("baseline_std_m", baseline_distance_std_m);
  }
};

// RawGNSSAttitudeOutput 11006, 52 bytes (spec §3.6.2 L2322-2349): ENU baseline vector.
struct RawGnssAttitudeOutputMessage {
  static constexpr MessageType kType = MessageType::kRawGnssAttitudeOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "RawGNSSAttitudeOutput";
  static constexpr std::size_t kSize = 52;
  MeasurementDetails details;
  std::uint8_t solution_type = 0;
  std::uint32_t flags = 0;
  std::array<float, 3> relative_position_enu_m{};
  std::array<float, 3> position_std_enu_m{};
  template <class V>
  void visit(V& v) {
    details.visit(v);
    v.field("solution_type", solution_type);
    v.reserved(3);
    v.field("flags", flags);
    v.field("rel_e_m", relative_position_enu_m[0]);
    v.field("rel_n_m", relative_position_enu_m[1]);
    v.field("rel_u_m", relative_position_enu_m[2]);
    v.field("std_e_m", position_std_enu_m[0]);
    v.field("std_n_m", position_std_enu_m[1]);
    v.field("std_u_m", position_std_enu_m[2]);
  }
};

// Wheel tick counts, 40 bytes: WheelTickInput 11103 (L2197-2214) = RawWheelTickOutput 11123.
struct WheelTickLayout {
  static constexpr std::size_t kSize = 40;
  MeasurementDetails details;
  std::array<std::uint32_t, 4> ticks{};  // FL, FR, RL, RR
  std::uint8_t gear = 0;
  template <class V>
  void visit(V& v) {
    details.visit(v);
    v.field("fl_ticks", ticks[0]);
    v.field("fr_ticks", ticks[1]);
    v.field("rl_ticks", ticks[2]);
    v.field("rr_ticks", ticks[3]);
    v.field("gear", gear);
    v.reserved(3);
  }
};
struct WheelTickInputMessage : WheelTickLayout {
  static constexpr MessageType kType = MessageType::kWheelTickInput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "WheelTickInput";
};
struct RawWheelTickOutputMessage : WheelTickLayout {
  static constexpr MessageType kType = MessageType::kRawWheelTickOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "RawWheelTickOutput";
};

// Single tick count, 28 bytes: VehicleTickInput 11104 (L2218-2232) = RawVehicleTickOutput 11124.
struct VehicleTickLayout {
  static constexpr std::size_t kSize = 28;
  MeasurementDetails details;
  std::uint32_t ticks = 0;
  std::uint8_t gear = 0;
  template <class V>
  void visit(V& v) {
    details.visit(v);
    v.field("ticks", ticks);
    v.field("gear", gear);
    v.reserved(3);
  }
};
struct VehicleTickInputMessage : VehicleTickLayout {
  static constexpr MessageType kType = MessageType::kVehicleTickInput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "VehicleTickInput";
};
struct RawVehicleTickOutputMessage : VehicleTickLayout {
  static constexpr MessageType kType = MessageType::kRawVehicleTickOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "RawVehicleTickOutput";
};

// Four wheel speeds as i32 * 2^-10 m/s, 40 bytes: WheelSpeedInput 11105 (L2236-2260) =
// RawWheelSpeedOutput 11125 (L2392-2416).
struct WheelSpeedLayout {
  static constexpr std::size_t kSize = 40;
  MeasurementDetails details;
  std::array<std::int32_t, 4> speed{kInvalidI32, kInvalidI32, kInvalidI32, kInvalidI32};
  std::uint8_t gear = 0;
  std::uint8_t flags = 0;
  template <class V>
  void visit(V& v) {
    details.visit(v);
    v.field("fl_speed_2^-10mps", speed[0]);
    v.field("fr_speed_2^-10mps", speed[1]);
    v.field("rl_speed_2^-10mps", speed[2]);
    v.field("rr_speed_2^-10mps", speed[3]);
    v.field("gear", gear);
    v.field("flags", flags);
    v.reserved(2);
  }
};
struct WheelSpeedInputMessage : WheelSpeedLayout {
  static constexpr MessageType kType = MessageType::kWheelSpeedInput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "WheelSpeedInput";
};
struct RawWheelSpeedOutputMessage : WheelSpeedLayout {
  static constexpr MessageType kType = MessageType::kRawWheelSpeedOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "RawWheelSpeedOutput";
};

// One speed as i32 * 2^-10 m/s, 28 bytes: VehicleSpeedInput 11106 (L2264-2287) =
// RawVehicleSpeedOutput 11126 (L2420-2441).
struct VehicleSpeedLayout {
  static constexpr std::size_t kSize = 28;
  MeasurementDetails details;
  std::int32_t speed = kInvalidI32;
  std::uint8_t gear = 0;
  std::uint8_t flags = 0;
  template <class V>
  void visit(V& v) {
    details.visit(v);
    v.field("speed_2^-10mps", speed);
    v.field("gear", gear);
    v.field("flags", flags);
    v.reserved(2);
  }
};
struct VehicleSpeedInputMessage : VehicleSpeedLayout {
  static constexpr MessageType kType = MessageType::kVehicleSpeedInput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "VehicleSpeedInput";
};
struct RawVehicleSpeedOutputMessage : VehicleSpeedLayout {
  static constexpr MessageType kType = MessageType::kRawVehicleSpeedOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "RawVehicleSpeedOutput";
};

// WheelSpeedOutput 11135, 28 bytes (spec §3.4.3 L2091-2120): corrected f32 speeds, NaN = n/a.
struct WheelSpeedOutputMessage {
  static constexpr MessageType kType = MessageType::kWheelSpeedOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "WheelSpeedOutput";
  static constexpr std::size_t kSize = 28;
  Timestamp p1_time;
  std::uint8_t data_source = 0;
  std::uint8_t gear = 0;
  std::uint8_t flags = 0;
  std::array<float, 4> speed_mps{};
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.field("data_source", data_source);
    v.field("gear", gear);
    v.field("flags", flags);
    v.reserved(1);
    v.field("fl_speed_mps", speed_mps[0]);
    v.field("fr_speed_mps", speed_mps[1]);
    v.field("rl_speed_mps", speed_mps[2]);
    v.field("rr_speed_mps", speed_mps[3]);
  }
};

// VehicleSpeedOutput 11136, 16 bytes (spec §3.4.4 L2124-2150).
struct VehicleSpeedOutputMessage {
  static constexpr MessageType kType = MessageType::kVehicleSpeedOutput;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "VehicleSpeedOutput";
  static constexpr std::size_t kSize = 16;
  Timestamp p1_time;
  std::uint8_t data_source = 0;
  std::uint8_t gear = 0;
  std::uint8_t flags = 0;
  float speed_mps = 0;
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.field("data_source", data_source);
    v.field("gear", gear);
    v.field("flags", flags);
    v.reserved(1);
    v.field("speed_mps", speed_mps);
  }
};

// InputDataWrapper 13120, 8 + N bytes (spec §3.6.7 L2445-2463): a u40 centisecond host time
// (5 little-endian bytes, read as its low 32 and high 8 bits), then wrapped raw bytes.
struct InputDataWrapperMessage {
  static constexpr MessageType kType = MessageType::kInputDataWrapper;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "InputDataWrapper";
  static constexpr std::size_t kSize = 8;
  static constexpr std::size_t kMaxVariableSize = kMaxOpaqueDataSize;  // "the rest of the payload"
  std::uint32_t system_time_cs_low = 0;
  std::uint8_t system_time_cs_high = 0;
  std::uint16_t data_type = 0;
  std::vector<std::uint8_t> data;
  std::uint64_t system_time_cs() const {
    return static_cast<std::uint64_t>(system_time_cs_high) << 32 | system_time_cs_low;
  }
  template <class V>
  void visit(V& v) {
    v.field("system_time_cs_low32", system_time_cs_low);
    v.field("system_time_cs_high8", system_time_cs_high);
    v.reserved(1);
    v.field("data_type", data_type);
    v.rest("data", data);
  }
};

}  // namespace navfuse::frontends::fusionengine

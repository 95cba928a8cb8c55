// Navigation solution output messages (spec §3.3, digest §5): wire layouts as visit() lists.
// Offsets are implied by field order; the digest's offset tables were checked against them by
// the size tests (tests/frontends/fusionengine/messages_layout_test.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

// Pose undulation "Set to -32768 if invalid" (spec L1736).
inline constexpr std::int16_t kInvalidUndulationCm = -32768;
inline constexpr std::uint8_t kPoseFlagStationary = 0x01;  // spec L1782

// PoseMessage 10000, version 2, 140 bytes (spec §3.3.1 L1721-1784, digest §5.1).
// Yaw/pitch/roll are ENU-referenced intrinsic 3-2-1 angles of the FLU body (spec §2.7 L635-653).
struct PoseMessage {
  static constexpr MessageType kType = MessageType::kPose;
  static constexpr std::uint8_t kVersion = 2;
  static constexpr std::string_view kName = "Pose";
  static constexpr std::size_t kSize = 140;
  Timestamp p1_time;
  Timestamp gps_time;
  std::uint8_t solution_type = 0;
  std::uint8_t flags = 0;
  std::int16_t undulation_cm = kInvalidUndulationCm;
  std::array<double, 3> lla_deg{};  // lat deg, lon deg, height above ellipsoid m
  std::array<float, 3> position_std_enu_m{};
  std::array<double, 3> ypr_deg{};
  std::array<float, 3> ypr_std_deg{};
  std::array<double, 3> velocity_body_mps{};  // forward, left, up
  std::array<float, 3> velocity_std_body_mps{};
  float aggregate_protection_level_m = 0;
  float horizontal_protection_level_m = 0;
  float vertical_protection_level_m = 0;
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.timestamp("gps_time", gps_time);
    v.field("solution_type", solution_type);
    v.field("flags", flags);
    v.field("undulation_cm", undulation_cm);
    v.field("lat_deg", lla_deg[0]);
    v.field("lon_deg", lla_deg[1]);
    v.field("alt_hae_m", lla_deg[2]);
    v.field("pos_std_e_m", position_std_enu_m[0]);
    v.field("pos_std_n_m", position_std_enu_m[1]);
    v.field("pos_std_u_m", position_std_enu_m[2]);
    v.field("yaw_deg", ypr_deg[0]);
    v.field("pitch_deg", ypr_deg[1]);
    v.field("roll_deg", ypr_deg[2]);
    v.field("yaw_std_deg", ypr_std_deg[0]);
    v.field("pitch_std_deg", ypr_std_deg[1]);
    v.field("roll_std_deg", ypr_std_deg[2]);
    v.field("vel_fwd_mps", velocity_body_mps[0]);
    v.field("vel_left_mps", velocity_body_mps[1]);
    v.field("vel_up_mps", velocity_body_mps[2]);
    v.field("vel_std_fwd_mps", velocity_std_body_mps[0]);
    v.field("vel_std_left_mps", velocity_std_body_mps[1]);
    v.field("vel_std_up_mps", velocity_std_body_mps[2]);
    v.field("aggregate_pl_m", aggregate_protection_level_m);
    v.field("horizontal_pl_m", horizontal_protection_level_m);
    v.field("vertical_pl_m", vertical_protection_level_m);
  }
};

// GNSSInfoMessage 10001, version 1, 48 bytes (spec §3.3.2 L1788-1811, digest §5.3).
inline constexpr std::uint8_t kInvalidLeapSecond = 0xFF;
inline constexpr std::uint16_t kInvalidU16 = 0xFFFF;
struct GnssInfoMessage {
  static constexpr MessageType kType = MessageType::kGnssInfo;
  static constexpr std::uint8_t kVersion = 1;
  static constexpr std::string_view kName = "GNSSInfo";
  static constexpr std::size_t kSize = 48;
  Timestamp p1_time;
  Timestamp gps_time;
  std::uint8_t leap_second_s = kInvalidLeapSecond;
  std::uint8_t num_svs = 0;
  std::uint16_t corrections_age_ds = kInvalidU16;      // 0.1 s units (L1804)
  std::uint16_t baseline_distance_dam = kInvalidU16;   // 10 m units (L1805)
  std::uint32_t reference_station_id = kInvalidU32;
  float gdop = 0, pdop = 0, hdop = 0, vdop = 0;
  float gps_time_std_s = 0;
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.timestamp("gps_time", gps_time);
    v.field("leap_second_s", leap_second_s);
    v.field("num_svs", num_svs);
    v.reserved(2);
    v.field("corrections_age_ds", corrections_age_ds);
    v.field("baseline_distance_10m", baseline_distance_dam);
    v.field("reference_station_id", reference_station_id);
    v.field("gdop", gdop);
    v.field("pdop", pdop);
    v.field("hdop", hdop);
    v.field("vdop", vdop);
    v.field("gps_time_std_s", gps_time_std_s);
  }
};

// GNSSSatelliteMessage 10002 (deprecated in v0.24), 20 + 12 N bytes (spec §3.3.3 L1815-1846).
struct SatelliteInfo {
  static constexpr std::size_t kSize = 12;
  std::uint8_t system = 0, prn = 0, usage = 0;
  // 0.25 dB-Hz units per upstream, not "dB-Hz" as L1838 says (digest §13 A17).
  std::uint8_t cn0_quarter_dbhz = 0;
  float azimuth_deg = 0, elevation_deg = 0;
  template <class V>
  void visit(V& v) {
    v.field("system", system);
    v.field("prn", prn);
    v.field("usage", usage);
    v.field("cn0_0p25dbhz", cn0_quarter_dbhz);
    v.field("azimuth_deg", azimuth_deg);
    v.field("elevation_deg", elevation_deg);
  }
};
struct GnssSatelliteMessage {
  static constexpr MessageType kType = MessageType::kGnssSatellite;
  static constexpr std::uint8_t kVersion = 1;
  static constexpr std::string_view kName = "GNSSSatellite";
  static constexpr std::size_t kSize = 20;
  Timestamp p1_time, gps_time;
  std::uint16_t num_satellites = 0;
  std::vector<SatelliteInfo> satellites;
  void sync_lengths() { num_satellites = static_cast<std::uint16_t>(satellites.size()); }
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.timestamp("gps_time", gps_time);
    v.field("num_satellites", num_satellites);
    v.reserved(2);
    v.list("sat", satellites, num_satellites);
  }
};

// PoseAux 10003, version 0, 160 bytes (spec §3.3.4 L1850-1872, digest §5.2).
struct PoseAuxMessage {
  static constexpr MessageType kType = MessageType::kPoseAux;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "PoseAux";
  static constexpr std::size_t kSize = 160;
  Timestamp p1_time;
  std::array<float, 3> position_std_body_m{};
  std::array<double, 9> position_cov_enu_m2{};  // row-major
  std::array<double, 4> attitude_quaternion{};  // x, y, z, w (scalar last, L1866)
  std::array<double, 3> velocity_enu_mps{};
  std::array<float, 3> velocity_std_enu_mps{};
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.field("pos_std_fwd_m", position_std_body_m[0]);
    v.field("pos_std_left_m", position_std_body_m[1]);
    v.field("pos_std_up_m", position_std_body_m[2]);
    v.array("pos_cov_enu_m2", position_cov_enu_m2);
    v.field("quat_x", attitude_quaternion[0]);
    v.field("quat_y", attitude_quaternion[1]);
    v.field("quat_z", attitude_quaternion[2]);
    v.field("quat_w", attitude_quaternion[3]);
    v.field("vel_e_mps", velocity_enu_mps[0]);
    v.field("vel_n_mps", velocity_enu_mps[1]);
    v.field("vel_u_mps", velocity_enu_mps[2]);
    v.field("vel_std_e_mps", velocity_std_enu_mps[0]);
    v.field("vel_std_n_mps", velocity_std_enu_mps[1]);
    v.field("vel_std_u_mps", velocity_std_enu_mps[2]);
  }
};

// CalibrationStatus 10004, version "1S" read as 1 (digest §13 A16), 92 bytes (L1876-1919).
enum class CalibrationStage : std::uint8_t { kUnknown = 0, kMountingAngle = 1, kDone = 0xFF };
struct CalibrationStatusMessage {
  static constexpr MessageType kType = MessageType::kCalibrationStatus;
  static constexpr std::uint8_t kVersion = 1;
  static constexpr std::string_view kName = "CalibrationStatus";
  static constexpr std::size_t kSize = 92;
  Timestamp p1_time;
  std::uint8_t calibration_stage = 0;
  std::array<float, 3> ypr_deg{};
  std::array<float, 3> ypr_std_deg{};
  float travel_distance_m = 0;
  std::uint8_t state_verified = 0;
  // 0.5 % units, [0, 200] (L1900-1902).
  std::uint8_t gyro_bias_half_percent = 0, accel_bias_half_percent = 0, mounting_half_percent = 0;
  float min_travel_distance_m = 0;
  std::array<float, 3> max_ypr_std_deg{};
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.field("calibration_stage", calibration_stage);
    v.reserved(3);
    v.field("mount_yaw_deg", ypr_deg[0]);
    v.field("mount_pitch_deg", ypr_deg[1]);
    v.field("mount_roll_deg", ypr_deg[2]);
    v.field("mount_yaw_std_deg", ypr_std_deg[0]);
    v.field("mount_pitch_std_deg", ypr_std_deg[1]);
    v.field("mount_roll_std_deg", ypr_std_deg[2]);
    v.field("travel_distance_m", travel_distance_m);
    v.reserved(24);
    v.field("state_verified", state_verified);
    v.reserved(3);
    v.field("gyro_bias_0p5pct", gyro_bias_half_percent);
    v.field("accel_bias_0p5pct", accel_bias_half_percent);
    v.field("mounting_angle_0p5pct", mounting_half_percent);
    v.reserved(5);
    v.field("min_travel_distance_m", min_travel_distance_m);
    v.field("max_yaw_std_deg", max_ypr_std_deg[0]);
    v.field("max_pitch_std_deg", max_ypr_std_deg[1]);
    v.field("max_roll_std_deg", max_ypr_std_deg[2]);
  }
};

// RelativeENUPosition 10005, 60 bytes (spec §3.3.6 L1922-1945).
struct RelativeEnuPositionMessage {
  static constexpr MessageType kType = MessageType::kRelativeEnuPosition;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "RelativeENUPosition";
  static constexpr std::size_t kSize = 60;
  Timestamp p1_time, gps_time;
  std::uint8_t solution_type = 0;
  std::uint32_t reference_station_id = kInvalidU32;
  std::array<double, 3> relative_position_enu_m{};
  std::array<float, 3> position_std_enu_m{};
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.timestamp("gps_time", gps_time);
    v.field("solution_type", solution_type);
    v.reserved(3);
    v.field("reference_station_id", reference_station_id);
    v.field("rel_e_m", relative_position_enu_m[0]);
    v.field("rel_n_m", relative_position_enu_m[1]);
    v.field("rel_u_m", relative_position_enu_m[2]);
    v.field("pos_std_e_m", position_std_enu_m[0]);
    v.field("pos_std_n_m", position_std_enu_m[1]);
    v.field("pos_std_u_m", position_std_enu_m[2]);
  }
};

// GNSSSignalsMessage 10006, version 1, 32 + 8 N + 8 S bytes (spec §3.3.7 L1949-2019).
struct GnssSatelliteEntry {
  static constexpr std::size_t kSize = 8;
  std::uint8_t system = 0, prn = 0, status_flags = 0;
  // 0.01 deg; invalid -128 per L1977 or 0x7FFF per upstream: both treated as invalid (A8).
  std::int16_t elevation_cdeg = 0x7FFF;
  std::uint16_t azimuth_cdeg = kInvalidU16;
  template <class V>
  void visit(V& v) {
    v.field("system", system);
    v.field("prn", prn);
    v.field("status_flags", status_flags);
    v.reserved(1);
    v.field("elevation_0p01deg", elevation_cdeg);
    v.field("azimuth_0p01deg", azimuth_cdeg);
  }
};
struct GnssSignalEntry {
  static constexpr std::size_t kSize = 8;
  std::uint16_t signal_type = 0;  // GNSSSignalType u16 (not u8 as L463 says, digest §13 B1)
  std::uint8_t prn = 0;
  std::uint8_t cn0_quarter_dbhz = 0;
  std::uint16_t status_flags = 0;
  template <class V>
  void visit(V& v) {
    v.field("signal_type", signal_type);
    v.field("prn", prn);
    v.field("cn0_0p25dbhz", cn0_quarter_dbhz);
    v.field("status_flags", status_flags);
    v.reserved(2);
  }
};
struct GnssSignalsMessage {
  static constexpr MessageType kType = MessageType::kGnssSignals;
  static constexpr std::uint8_t kVersion = 1;
  static constexpr std::string_view kName = "GNSSSignals";
  static constexpr std::size_t kSize = 32;
  Timestamp p1_time, gps_time;
  std::uint32_t gps_tow_ms = kInvalidU32;
  std::uint16_t gps_week = kInvalidU16;
  std::uint16_t num_signals = 0;
  std::uint8_t num_satellites = 0;
  std::vector<GnssSatelliteEntry> satellites;
  std::vector<GnssSignalEntry> signals;
  void sync_lengths() {
    num_satellites = static_cast<std::uint8_t>(satellites.size());
    num_signals = static_cast<std::uint16_t>(signals.size());
  }
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.timestamp("gps_time", gps_time);
    v.field("gps_tow_ms", gps_tow_ms);
    v.field("gps_week", gps_week);
    v.field("num_signals", num_signals);
    v.field("num_satellites", num_satellites);
    v.reserved(7);
    v.list("sat", satellites, num_satellites);
    v.list("sig", signals, num_signals);
  }
};

}  // namespace navfuse::frontends::fusionengine

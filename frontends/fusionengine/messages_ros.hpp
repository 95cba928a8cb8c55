// ROS-style output messages (spec §3.9 L2708-2830, digest §8.7): "not guaranteed to be
// byte-compatible with ROS messages" (L2712).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

// ROSPose 12000, 64 bytes: ENU offset from the first valid pose + body->ENU quaternion (x,y,z,w).
struct RosPoseMessage {
  static constexpr MessageType kType = MessageType::kRosPose;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "ROSPose";
  static constexpr std::size_t kSize = 64;
  Timestamp p1_time;
  std::array<double, 3> position_rel_m{};
  std::array<double, 4> orientation{};
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.field("rel_e_m", position_rel_m[0]);
    v.field("rel_n_m", position_rel_m[1]);
    v.field("rel_u_m", position_rel_m[2]);
    v.field("quat_x", orientation[0]);
    v.field("quat_y", orientation[1]);
    v.field("quat_z", orientation[2]);
    v.field("quat_w", orientation[3]);
  }
};

// ROSGPSFix 12010, 284 bytes (L2737-2790). GPS Time is an f64 of seconds since 1980-01-06 as
// upstream has it, not the "Timestamp (8B)" of L2760 (digest §13 A12; same size). Track error
// is in degrees as upstream says, not "meters" (L2769, digest §13 B22).
enum class CovarianceType : std::uint8_t { kUnknown = 0, kApproximated = 1, kDiagonalKnown = 2, kKnown = 3 };
struct RosGpsFixMessage {
  static constexpr MessageType kType = MessageType::kRosGpsFix;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "ROSGPSFix";
  static constexpr std::size_t kSize = 284;
  Timestamp p1_time;
  double latitude_deg = 0, longitude_deg = 0, altitude_m = 0;
  double track_deg = 0, speed_mps = 0, climb_mps = 0;
  double pitch_deg = 0, roll_deg = 0, dip_deg = 0;
  double gps_time_s = 0;
  double gdop = 0, pdop = 0, hdop = 0, vdop = 0, tdop = 0;
  double err_3d_m = 0, err_horizontal_m = 0, err_vertical_m = 0, err_track_deg = 0;
  double err_speed_mps = 0, err_climb_mps = 0, err_time_s = 0;
  double err_pitch_deg = 0, err_roll_deg = 0, err_dip_deg = 0;
  std::array<double, 9> position_covariance_m2{};  // ENU, row-major
  std::uint8_t position_covariance_type = 0;
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.field("lat_deg", latitude_deg);
    v.field("lon_deg", longitude_deg);
    v.field("alt_hae_m", altitude_m);
    v.field("track_deg", track_deg);
    v.field("speed_mps", speed_mps);
    v.field("climb_mps", climb_mps);
    v.field("pitch_deg", pitch_deg);
    v.field("roll_deg", roll_deg);
    v.field("dip_deg", dip_deg);
    v.field("gps_time_s", gps_time_s);
    v.field("gdop", gdop);
    v.field("pdop", pdop);
    v.field("hdop", hdop);
    v.field("vdop", vdop);
    v.field("tdop", tdop);
    v.field("err_3d_m", err_3d_m);
    v.field("err_horizontal_m", err_horizontal_m);
    v.field("err_vertical_m", err_vertical_m);
    v.field("err_track_deg", err_track_deg);
    v.field("err_speed_mps", err_speed_mps);
    v.field("err_climb_mps", err_climb_mps);
    v.field("err_time_s", err_time_s);
    v.field("err_pitch_deg", err_pitch_deg);
    v.field("err_roll_deg", err_roll_deg);
    v.field("err_dip_deg", err_dip_deg);
    v.array("pos_cov_enu_m2", position_covariance_m2);
    v.field("pos_cov_type", position_covariance_type);
    v.reserved(3);
  }
};

// ROSIMUMessage 12011, 304 bytes (L2794-2830): output only.
struct RosImuMessage {
  static constexpr MessageType kType = MessageType::kRosImu;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "ROSIMU";
  static constexpr std::size_t kSize = 304;
  Timestamp p1_time;
  std::array<double, 4> orientation{};  // x, y, z, w
  std::array<double, 9> orientation_covariance{};
  std::array<double, 3> angular_velocity_rps{};
  std::array<double, 9> angular_velocity_covariance{};
  std::array<double, 3> acceleration_mps2{};
  std::array<double, 9> acceleration_covariance{};
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.array("quat_xyzw", orientation);
    v.array("orientation_cov_rad2", orientation_covariance);
    v.array("gyro_rps", angular_velocity_rps);
    v.array("gyro_cov_rps2", angular_velocity_covariance);
    v.array("accel_mps2", acceleration_mps2);
    v.array("accel_cov_m2ps4", acceleration_covariance);
  }
};

}  // namespace navfuse::frontends::fusionengine

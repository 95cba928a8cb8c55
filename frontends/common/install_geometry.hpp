// The config's installation geometry as the devices take it (`navfuse run --configure-device`):
// shared by the front-ends that send it (frontends/*/commands*).
#pragma once

#include <Eigen/Core>

#include "core/config/config.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::frontends {

// A config vector (vehicle frame FRD, metres) in the frame the device streams its IMU data in.
// navfuse rotates that frame into the vehicle by imu.mounting_rpy_deg (DESIGN.md conventions:
// v_vehicle = C_vs v_sensor, C_vs = Rz(yaw) Ry(pitch) Rx(roll)), so a device whose own lever
// arms are given in its output frame (VN-300 body frame, Reg 57/93; CV7 vehicle frame, 0x0D,0x54)
// needs C_vs^T r. This holds whatever rotation the device itself applies (VN Reg 26, CV7
// 0x0C,0x31): navfuse's mounting starts from the frame the device outputs.
inline Eigen::Vector3d in_device_output_frame(const config::Config& config, const config::Vec3& vehicle_frd_m) {
  const auto& m = config.imu.mounting_rpy_deg;
  const Eigen::Matrix3d c_vs = rot::dcm_from_rpy(Eigen::Vector3d(m[0], m[1], m[2]) * rot::kDegToRad);
  return c_vs.transpose() * Eigen::Vector3d(vehicle_frd_m[0], vehicle_frd_m[1], vehicle_frd_m[2]);
}

// gnss.secondary_lever_arm_m left at zero means "no second antenna" (config comment).
inline bool has_secondary_antenna(const config::Config& config) {
  const auto& s = config.gnss.secondary_lever_arm_m;
  return s[0] != 0 || s[1] != 0 || s[2] != 0;
}

}  // namespace navfuse::frontends

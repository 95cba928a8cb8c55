// One step of a device's set-up (`navfuse run --configure-device`): the command bytes and, for a
// read-back, the check of the device's answer against what was written before. The front-end
// that speaks the protocol builds the steps from the config (FrontendInfo::setup_steps); the
// apps send them in order and stop at the first refusal or failed check.
#pragma once

#include <cstdio>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/config/config.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/common/device_command.hpp"

namespace navfuse::frontends {

struct SetupStep {
  DeviceCommand command;
  // Given every byte the device sent after `command`: "" when it holds the value written, else
  // one line naming the setting with the value sent and the value read (or that none came).
  // Empty for commands that read nothing back.
  std::function<std::string(std::span<const std::uint8_t>)> verify;
  // For a write of a setting: "<setting> to (values)", so that a refusal names what was sent.
  std::string sets;
};

// Steps without read-back checks.
inline std::vector<SetupStep> steps_from_commands(std::vector<DeviceCommand> commands) {
  std::vector<SetupStep> out;
  out.reserve(commands.size());
  for (DeviceCommand& c : commands) out.push_back({std::move(c), {}, {}});
  return out;
}

inline std::string vector_text(const Eigen::VectorXd& v) {
  std::string out = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%.4f", i == 0 ? "" : ", ", v[i]);
    out += buf;
  }
  return out + ")";
}

// SetupStep::sets of a vector setting.
inline std::string setting_to(std::string_view setting, const Eigen::VectorXd& value) {
  return std::string(setting) + " to " + vector_text(value);
}

// The read-back verdict for a vector setting: "" when `read` has every component within
// `tolerance` of `sent`; otherwise "<setting>: sent (..), read (..)" or "..., no read-back reply".
inline std::string compare_read_back(std::string_view setting, const Eigen::VectorXd& sent,
                                     const std::optional<Eigen::VectorXd>& read, double tolerance) {
  const std::string head = std::string(setting) + ": sent " + vector_text(sent);
  if (!read) return head + ", no read-back reply";
  if (read->size() == sent.size() && ((*read - sent).array().abs() <= tolerance).all()) return {};
  return head + ", read " + vector_text(*read);
}

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

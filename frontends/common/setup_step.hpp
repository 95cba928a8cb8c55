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

}  // namespace navfuse::frontends

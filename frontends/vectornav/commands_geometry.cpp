#include "frontends/vectornav/commands_geometry.hpp"

#include <string_view>

#include "frontends/vectornav/ascii_registers.hpp"

namespace navfuse::frontends::vectornav::cmd {
namespace {

constexpr std::string_view kReadReply = "$VNRRG,";

constexpr std::string_view kAntennaSetting = "VN-300 GNSS antenna A offset (Reg 57, body frame, m)";
constexpr std::string_view kBaselineSetting = "VN-300 GNSS compass baseline and uncertainty (Reg 93, body frame, m)";

Eigen::VectorXd stacked(const CompassBaseline& b) {
  Eigen::VectorXd v(6);
  v << b.baseline_m, b.uncertainty_m;
  return v;
}

}  // namespace

FusionSetup fusion_setup_from_config(const config::Config& config) {
  FusionSetup s;
  s.antenna_a_offset_m = in_device_output_frame(config, config.gnss.lever_arm_m);
  if (has_secondary_antenna(config)) {
    s.compass_baseline_m = in_device_output_frame(config, config.gnss.secondary_lever_arm_m) - *s.antenna_a_offset_m;
    s.compass_baseline_std_m.setConstant(config.gnss.baseline_std_m);
  }
  return s;
}

std::optional<Reply> find_register_reply(std::span<const std::uint8_t> reply_bytes, int register_id) {
  const std::string_view text(reinterpret_cast<const char*>(reply_bytes.data()), reply_bytes.size());
  for (std::size_t at = text.find(kReadReply); at != std::string_view::npos; at = text.find(kReadReply, at + 1)) {
    const std::size_t end = text.find_first_of("\r\n", at);
    const auto reply = parse_reply(text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
    if (reply && reply->kind == Reply::Kind::kRegister && reply->register_id == register_id) return reply;
  }
  return std::nullopt;
}

std::string verify_antenna_offset(std::span<const std::uint8_t> reply_bytes, const Eigen::Vector3d& sent_m) {
  std::optional<Eigen::VectorXd> read;
  if (const auto reply = find_register_reply(reply_bytes, reg::kGnssAntennaA)) {
    if (const auto v = parse_vector3(*reply, reg::kGnssAntennaA)) read = Eigen::VectorXd(*v);
  }
  return compare_read_back(kAntennaSetting, sent_m, read, kReadBackToleranceM);
}

std::string verify_compass_baseline(std::span<const std::uint8_t> reply_bytes, const CompassBaseline& sent) {
  std::optional<Eigen::VectorXd> read;
  if (const auto reply = find_register_reply(reply_bytes, reg::kCompassBaseline)) {
    if (const auto b = parse_compass_baseline(*reply)) read = stacked(*b);
  }
  return compare_read_back(kBaselineSetting, stacked(sent), read, kReadBackToleranceM);
}

std::vector<SetupStep> fusion_setup_steps(const config::Config& config) {
  const FusionSetup setup = fusion_setup_from_config(config);
  std::vector<std::string> sentences = fusion_setup_commands(setup);
  // The sequence ends by resuming the asynchronous output (commands.hpp): the read-backs go
  // before it, while the port carries nothing but replies.
  const std::string resume = sentences.back();
  sentences.pop_back();
  std::vector<SetupStep> steps = steps_from_commands(commands_from_sentences(sentences));
  // Names what a geometry write sets, for the report of a refusal.
  auto name_write = [&](const std::string& write, std::string sets) {
    for (SetupStep& s : steps) {
      if (std::string_view(reinterpret_cast<const char*>(s.command.data()), s.command.size()) == write) s.sets = sets;
    }
  };
  auto add_read = [&](int id, std::function<std::string(std::span<const std::uint8_t>)> verify) {
    const std::string read = read_register(id);
    steps.push_back({DeviceCommand(read.begin(), read.end()), std::move(verify), {}});
  };
  const Eigen::Vector3d antenna = *setup.antenna_a_offset_m;
  name_write(write_antenna_offset(Antenna::kInternalA, antenna), setting_to(kAntennaSetting, antenna));
  add_read(reg::kGnssAntennaA, [antenna](std::span<const std::uint8_t> r) { return verify_antenna_offset(r, antenna); });
  if (setup.compass_baseline_m) {
    const CompassBaseline baseline{*setup.compass_baseline_m, setup.compass_baseline_std_m};
    name_write(write_compass_baseline(baseline.baseline_m, baseline.uncertainty_m),
               setting_to(kBaselineSetting, stacked(baseline)));
    add_read(reg::kCompassBaseline,
             [baseline](std::span<const std::uint8_t> r) { return verify_compass_baseline(r, baseline); });
  }
  steps.push_back({DeviceCommand(resume.begin(), resume.end()), {}, {}});
  return steps;
}

}  // namespace navfuse::frontends::vectornav::cmd

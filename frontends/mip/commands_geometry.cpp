#include "frontends/mip/commands_geometry.hpp"

#include <cstdio>
#include <variant>

#include "core/bytes/byte_reader.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/packet.hpp"

namespace navfuse::frontends::mip {
namespace {

constexpr std::uint8_t kPrimaryReceiver = 1, kSecondaryReceiver = 2;       // CV7 numbering (digest §6.9)
constexpr std::size_t kKeyedVectorKeys = 1;  // receiver id / source
// The device stores f32 and returns it as written: only the f32 rounding of the sent double.
constexpr double kReadBackToleranceM = 1e-6;

std::string nack_text(std::string_view setting, ReplyCode code) {
  char text[32];
  std::snprintf(text, sizeof text, "%u", static_cast<unsigned>(code));
  return std::string(setting) + ": read-back refused (MIP NACK " + text + ")";
}

}  // namespace

std::string verify_vector_setting(std::span<const std::uint8_t> reply_bytes, std::uint8_t desc_set, std::uint8_t desc,
                                  std::uint8_t key, const Eigen::Vector3d& sent_m, std::string_view setting) {
  std::optional<Eigen::VectorXd> read;
  std::optional<ReplyCode> refused;
  Framer framer;
  std::vector<ReplyEntry> entries;
  framer.feed(reply_bytes, [&](const PacketView& p) {
    if (p.desc_set != desc_set || read || refused || !parse_reply(p.payload, entries)) return;
    for (const ReplyEntry& e : entries) {
      if (e.cmd_desc != desc) continue;
      if (e.code != ReplyCode::kAck) {
        refused = e.code;
        return;
      }
      bytes::BeReader r(e.response_data);
      const std::uint8_t got_key = r.u8();
      const double x = r.f32(), y = r.f32(), z = r.f32();
      if (r.ok() && got_key == key) read = Eigen::Vector3d(x, y, z);
      return;
    }
  });
  if (refused) return nack_text(setting, *refused);
  return compare_read_back(setting, sent_m, read, kReadBackToleranceM);
}

std::vector<SetupStep> cv7_setup_steps(const config::Config& config) {
  std::vector<std::vector<std::uint8_t>> packets = cv7_setup_sequence();
  // The sequence ends with Resume (commands.hpp): the geometry goes in while the device is idle.
  std::vector<std::uint8_t> resume_packet = std::move(packets.back());
  packets.pop_back();
  std::vector<SetupStep> steps = steps_from_commands(std::move(packets));
  // Each write's key (receiver id, source) is its first parameter after the function selector.
  auto add = [&](const Command& write, const Eigen::Vector3d& value, std::string setting) {
    const auto key = static_cast<std::uint8_t>(std::get<std::uint64_t>(write.values.at(1)));
    if (auto p = build_command_packet(write)) steps.push_back({std::move(*p), {}, setting_to(setting, value)});
    if (auto p = build_command_packet(read_of(write, kKeyedVectorKeys))) {
      steps.push_back({std::move(*p),
                       [=, setting = std::move(setting)](std::span<const std::uint8_t> reply) {
                         return verify_vector_setting(reply, write.desc_set, write.desc, key, value, setting);
                       },
                       {}});
    }
  };
  const Eigen::Vector3d primary = in_device_output_frame(config, config.gnss.lever_arm_m);
  add(antenna_offset(kPrimaryReceiver, primary), primary,
      "CV7 GNSS antenna 1 offset (0x0D,0x54, device vehicle frame, m)");
  if (has_secondary_antenna(config)) {
    const Eigen::Vector3d secondary = in_device_output_frame(config, config.gnss.secondary_lever_arm_m);
    add(antenna_offset(kSecondaryReceiver, secondary), secondary,
        "CV7 GNSS antenna 2 offset (0x0D,0x54, device vehicle frame, m)");
  }
  const Eigen::Vector3d wheel = in_device_output_frame(config, config.wheel.lever_arm_m);
  add(speed_lever_arm(wheel), wheel, "CV7 speed measurement lever arm (0x0D,0x61, device vehicle frame, m)");
  steps.push_back({std::move(resume_packet), {}, {}});
  return steps;
}

}  // namespace navfuse::frontends::mip

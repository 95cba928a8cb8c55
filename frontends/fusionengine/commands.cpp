#include "frontends/fusionengine/commands.hpp"

#include <cstdio>

#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/message_catalog.hpp"
#include "frontends/fusionengine/messages_control.hpp"
#include "frontends/fusionengine/payload_reader.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

std::string_view response_name(std::uint8_t code) {
  switch (static_cast<Response>(code)) {
    case Response::kOk: return "OK";
    case Response::kUnsupportedMessageVersion: return "unsupported message version";
    case Response::kUnsupportedFeature: return "unsupported feature";
    case Response::kValueError: return "value error";
    case Response::kInsufficientSpace: return "insufficient space";
    case Response::kExecutionFailure: return "execution failure";
    case Response::kInconsistentPayloadLength: return "inconsistent payload length";
    case Response::kDataCorrupted: return "data corrupted";
    case Response::kNoDataStored: return "no data stored";
    case Response::kUnavailable: return "unavailable";
    case Response::kUnsupportedInterface: return "unsupported interface";
  }
  return "unknown code";
}

std::string refusal_text(std::string_view message, std::uint8_t code) {
  return "FusionEngine " + std::string(message) + " response " + std::to_string(code) + " (" +
         std::string(response_name(code)) + ")";
}

Eigen::VectorXd vector_of(const Point3f& p) { return Eigen::Vector3d(p.xyz_m[0], p.xyz_m[1], p.xyz_m[2]); }

std::string setting_name(ConfigType type) {
  char text[96];
  std::snprintf(text, sizeof text, "FusionEngine %s (ConfigType 0x%02X, body FLU, m)",
                std::string(to_string(type)).c_str(), static_cast<unsigned>(to_u16(type)));
  return text;
}

// The messages navfuse decodes from a device (to_core.hpp) and the rate it wants them at.
constexpr MessageType kFusedMessages[] = {MessageType::kImuOutput, MessageType::kPose, MessageType::kGnssInfo};
constexpr MessageRate kFusedRate = MessageRate::kOnChange;
constexpr InterfaceId kCurrentInterface{static_cast<std::uint8_t>(TransportType::kCurrent), 0};

std::string rate_setting_name(MessageType message) {
  return "FusionEngine " + std::string(message_name(to_u16(message)).value_or("message")) + " (" +
         std::to_string(to_u16(message)) + ") output rate (SetMessageRate, current interface)";
}

}  // namespace

std::vector<std::uint8_t> set_message_rate(FusionEngineWriter& writer, MessageType message, MessageRate rate,
                                           const InterfaceId& iface) {
  SetMessageRateMessage m;
  m.output_interface = iface;
  m.protocol = static_cast<std::uint8_t>(ProtocolType::kFusionEngine);
  m.message_id = to_u16(message);
  m.rate = static_cast<std::uint8_t>(rate);
  return writer.frame(m);
}

std::vector<std::uint8_t> get_message_rate(FusionEngineWriter& writer, MessageType message, const InterfaceId& iface) {
  GetMessageRateMessage m;
  m.output_interface = iface;
  m.protocol = static_cast<std::uint8_t>(ProtocolType::kFusionEngine);
  m.source = static_cast<std::uint8_t>(ConfigSource::kActive);
  m.message_id = to_u16(message);
  return writer.frame(m);
}

std::string verify_message_rate(std::span<const std::uint8_t> reply_bytes, MessageType message, MessageRate sent) {
  std::optional<std::uint8_t> read;
  std::string refused;
  Framer framer;
  framer.feed(reply_bytes, [&](const Frame& f) {
    MessageRateResponseMessage r;
    if (read || !refused.empty() || f.header.message_type != to_u16(MessageType::kMessageRateResponse) ||
        !decode_payload(f.payload, r)) {
      return;
    }
    if (r.response != static_cast<std::uint8_t>(Response::kOk)) {
      refused = refusal_text("MessageRateResponse", r.response);
      return;
    }
    for (const MessageRateEntry& e : r.rates) {
      if (e.message_id == to_u16(message)) read = e.configured_rate;
    }
  });
  const std::string setting = rate_setting_name(message);
  if (!refused.empty()) return setting + ": read-back refused (" + refused + ")";
  const std::string sent_text = "sent rate " + std::to_string(static_cast<unsigned>(sent));
  if (!read) return setting + ": " + sent_text + ", no read-back reply";
  if (*read == static_cast<std::uint8_t>(sent)) return {};
  return setting + ": " + sent_text + ", read rate " + std::to_string(static_cast<unsigned>(*read));
}

std::vector<std::uint8_t> set_point_config(FusionEngineWriter& writer, ConfigType type, const Point3f& value) {
  SetConfigMessage m;
  m.config_type = to_u16(type);
  m.value = pack_config(value);
  return writer.frame(m);
}

std::vector<std::uint8_t> get_config(FusionEngineWriter& writer, ConfigType type) {
  GetConfigMessage m;
  m.config_type = to_u16(type);
  m.source = static_cast<std::uint8_t>(ConfigSource::kActive);
  return writer.frame(m);
}

std::string verify_point_config(std::span<const std::uint8_t> reply_bytes, ConfigType type, const Point3f& sent) {
  std::optional<Eigen::VectorXd> read;
  std::string refused;
  Framer framer;
  framer.feed(reply_bytes, [&](const Frame& f) {
    ConfigResponseMessage r;
    if (read || !refused.empty() || f.header.message_type != to_u16(MessageType::kConfigResponse) ||
        !decode_payload(f.payload, r) || r.config_type != to_u16(type)) {
      return;
    }
    if (r.response != static_cast<std::uint8_t>(Response::kOk)) {
      refused = refusal_text("ConfigResponse", r.response);
    } else if (const auto p = parse_config<Point3f>(r.value); p && r.value.size() == Point3f::kSize) {
      read = vector_of(*p);
    }
  });
  if (!refused.empty()) return setting_name(type) + ": read-back refused (" + refused + ")";
  // The device keeps the f32 it was given: equal bits.
  return compare_read_back(setting_name(type), vector_of(sent), read, 0.0);
}

std::vector<SetupStep> fusion_setup_steps(const config::Config& config) {
  FusionEngineWriter writer;
  std::vector<SetupStep> steps;
  auto add = [&](ConfigType type, const Point3f& value) {
    steps.push_back({set_point_config(writer, type, value), {}, setting_to(setting_name(type), vector_of(value))});
    steps.push_back({get_config(writer, type),
                     [type, value](std::span<const std::uint8_t> reply) { return verify_point_config(reply, type, value); },
                     {}});
  };
  add(ConfigType::kDeviceLeverArm, Point3f{});
  add(ConfigType::kGnssLeverArm, point_from_frd(config.gnss.lever_arm_m));
  if (has_secondary_antenna(config)) add(ConfigType::kGnssAuxLeverArm, point_from_frd(config.gnss.secondary_lever_arm_m));
  for (const MessageType message : kFusedMessages) {
    steps.push_back({set_message_rate(writer, message, kFusedRate, kCurrentInterface), {},
                     rate_setting_name(message) + " to rate " + std::to_string(static_cast<unsigned>(kFusedRate))});
    steps.push_back({get_message_rate(writer, message, kCurrentInterface),
                     [message](std::span<const std::uint8_t> reply) { return verify_message_rate(reply, message, kFusedRate); },
                     {}});
  }
  return steps;
}

std::string find_refusal(std::span<const std::uint8_t> reply_bytes) {
  std::string refusal;
  Framer framer;
  framer.feed(reply_bytes, [&](const Frame& f) {
    if (!refusal.empty()) return;
    if (f.header.message_type == to_u16(MessageType::kCommandResponse)) {
      CommandResponseMessage r;
      if (decode_payload(f.payload, r) && r.response != static_cast<std::uint8_t>(Response::kOk)) {
        refusal = refusal_text("CommandResponse", r.response);
      }
    } else if (f.header.message_type == to_u16(MessageType::kConfigResponse)) {
      ConfigResponseMessage r;
      if (decode_payload(f.payload, r) && r.response != static_cast<std::uint8_t>(Response::kOk)) {
        refusal = refusal_text("ConfigResponse", r.response);
      }
    }
  });
  return refusal;
}

}  // namespace navfuse::frontends::fusionengine

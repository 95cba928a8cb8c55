#include "frontends/fusionengine/responder.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"
#include "frontends/fusionengine/payload_reader.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

using rot::kDegToRad;
using rot::kRadToDeg;

bool finite(const Point3f& p) {
  return std::isfinite(p.xyz_m[0]) && std::isfinite(p.xyz_m[1]) && std::isfinite(p.xyz_m[2]);
}

// CoarseOrientation directions as FLU unit vectors (spec L1056-1065).
std::optional<Eigen::Vector3d> axis_of(std::uint8_t d) {
  switch (static_cast<Direction>(d)) {
    case Direction::kForward: return Eigen::Vector3d::UnitX();
    case Direction::kBackward: return -Eigen::Vector3d::UnitX();
    case Direction::kLeft: return Eigen::Vector3d::UnitY();
    case Direction::kRight: return -Eigen::Vector3d::UnitY();
    case Direction::kUp: return Eigen::Vector3d::UnitZ();
    case Direction::kDown: return -Eigen::Vector3d::UnitZ();
    default: return std::nullopt;
  }
}
std::uint8_t direction_of(const Eigen::Vector3d& v) {
  for (std::uint8_t d = 0; d <= static_cast<std::uint8_t>(Direction::kDown); ++d) {
    if (axis_of(d)->dot(v) > 0.999) return d;
  }
  return static_cast<std::uint8_t>(Direction::kInvalid);
}
const Eigen::Matrix3d kFrdFromFlu = Eigen::Vector3d(1, -1, -1).asDiagonal();

// IMU axes in the vehicle -> mounting roll/pitch/yaw of sensor -> vehicle (FRD), degrees.
std::optional<config::Vec3> mounting_from(const CoarseOrientation& o) {
  const auto x = axis_of(o.x_direction), z = axis_of(o.z_direction);
  if (!x || !z || std::abs(x->dot(*z)) > 0.5) return std::nullopt;
  Eigen::Matrix3d c_flu_imu;
  c_flu_imu.col(0) = *x;
  c_flu_imu.col(1) = z->cross(*x);
  c_flu_imu.col(2) = *z;
  const Eigen::Vector3d rpy = rot::rpy_from_dcm(kFrdFromFlu * c_flu_imu) * kRadToDeg;
  return config::Vec3{rpy.x(), rpy.y(), rpy.z()};
}
CoarseOrientation orientation_from(const config::Vec3& mounting_rpy_deg) {
  const Eigen::Matrix3d c_flu_imu =
      kFrdFromFlu * rot::dcm_from_rpy(Eigen::Vector3d(mounting_rpy_deg[0], mounting_rpy_deg[1], mounting_rpy_deg[2]) * kDegToRad);
  return {direction_of(c_flu_imu.col(0)), direction_of(c_flu_imu.col(2))};
}

template <class C>
std::optional<C> parse_exact(std::span<const std::uint8_t> value) {
  if (value.size() != C::kSize) return std::nullopt;
  return parse_config<C>(value);
}

}  // namespace

bool DeviceControl::State::operator==(const State& o) const {
  return pack_config(point_from_frd(config.gnss.lever_arm_m)) == pack_config(point_from_frd(o.config.gnss.lever_arm_m)) &&
         pack_config(point_from_frd(config.gnss.secondary_lever_arm_m)) ==
             pack_config(point_from_frd(o.config.gnss.secondary_lever_arm_m)) &&
         config.imu.mounting_rpy_deg == o.config.imu.mounting_rpy_deg &&
         pack_config(device_lever_arm) == pack_config(o.device_lever_arm) &&
         pack_config(output_lever_arm) == pack_config(o.output_lever_arm) &&
         pack_config(vehicle) == pack_config(o.vehicle) && pack_config(wheel) == pack_config(o.wheel);
}

DeviceControl::DeviceControl(const config::Config& config, VersionStrings versions)
    : versions_(std::move(versions)) {
  default_.config = config;
  active_ = saved_ = default_;
}

const DeviceControl::State& DeviceControl::state_for(std::uint8_t source) const {
  switch (static_cast<ConfigSource>(source)) {
    case ConfigSource::kSaved: return saved_;
    case ConfigSource::kDefault: return default_;
    default: return active_;
  }
}

void DeviceControl::feed(std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& responses) {
  framer_.feed(bytes, [&](const Frame& f) { respond(f, writer_, responses); });
}

void DeviceControl::respond(const Frame& frame, FusionEngineWriter& writer, std::vector<std::uint8_t>& out) {
  const State before = active_;
  on_frame(frame, writer, out);
  if (!(active_ == before)) ++config_changes_;
}

std::optional<std::vector<std::uint8_t>> DeviceControl::config_value(const State& s, std::uint16_t type) const {
  switch (static_cast<ConfigType>(type)) {
    case ConfigType::kDeviceLeverArm: return pack_config(s.device_lever_arm);
    case ConfigType::kOutputLeverArm: return pack_config(s.output_lever_arm);
    case ConfigType::kGnssLeverArm: return pack_config(point_from_frd(s.config.gnss.lever_arm_m));
    case ConfigType::kGnssAuxLeverArm: return pack_config(point_from_frd(s.config.gnss.secondary_lever_arm_m));
    case ConfigType::kDeviceCoarseOrientation: return pack_config(orientation_from(s.config.imu.mounting_rpy_deg));
    case ConfigType::kVehicleDetails: return pack_config(s.vehicle);
    case ConfigType::kWheelConfig: return pack_config(s.wheel);
    default: return std::nullopt;
  }
}

Response DeviceControl::apply_config_value(State& s, std::uint16_t type, std::span<const std::uint8_t> value) const {
  const std::size_t expected = config_value_size(type);
  if (!config_value(s, type)) return Response::kUnsupportedFeature;
  if (value.size() != expected) return Response::kInconsistentPayloadLength;
  switch (static_cast<ConfigType>(type)) {
    case ConfigType::kDeviceLeverArm:
    case ConfigType::kOutputLeverArm:
    case ConfigType::kGnssLeverArm:
    case ConfigType::kGnssAuxLeverArm: {
      const auto p = parse_exact<Point3f>(value);
      if (!p || !finite(*p)) return Response::kValueError;
      if (type == to_u16(ConfigType::kDeviceLeverArm)) s.device_lever_arm = *p;
      if (type == to_u16(ConfigType::kOutputLeverArm)) s.output_lever_arm = *p;
      if (type == to_u16(ConfigType::kGnssLeverArm)) s.config.gnss.lever_arm_m = frd_from_point(*p);
      if (type == to_u16(ConfigType::kGnssAuxLeverArm)) s.config.gnss.secondary_lever_arm_m = frd_from_point(*p);
      return Response::kOk;
    }
    case ConfigType::kDeviceCoarseOrientation: {
      const auto o = parse_exact<CoarseOrientation>(value);
      const auto mounting = o ? mounting_from(*o) : std::nullopt;
      if (!mounting) return Response::kValueError;
      s.config.imu.mounting_rpy_deg = *mounting;
      return Response::kOk;
    }
    case ConfigType::kVehicleDetails: {
      const auto v = parse_exact<VehicleDetails>(value);
      if (!v || !std::isfinite(v->wheelbase_m) || !std::isfinite(v->front_track_width_m) ||
          !std::isfinite(v->rear_track_width_m)) {
        return Response::kValueError;
      }
      s.vehicle = *v;
      return Response::kOk;
    }
    case ConfigType::kWheelConfig: {
      const auto w = parse_exact<WheelConfig>(value);
      if (!w || w->wheel_sensor_type > static_cast<std::uint8_t>(WheelSensorType::kVehicleTicks)) {
        return Response::kValueError;
      }
      s.wheel = *w;
      return Response::kOk;
    }
    default:
      return Response::kUnsupportedFeature;
  }
}

Response DeviceControl::set_config(const SetConfigMessage& m) {
  if ((m.flags & kConfigFlagRevertToDefault) != 0) {
    // "Reset both the active and saved configuration to default values" (L958).
    const auto value = config_value(default_, m.config_type);
    if (!value) return Response::kUnsupportedFeature;
    apply_config_value(active_, m.config_type, *value);
    apply_config_value(saved_, m.config_type, *value);
    return Response::kOk;
  }
  State next = active_;
  const Response r = apply_config_value(next, m.config_type, m.value);
  if (r != Response::kOk) return r;
  active_ = next;
  if ((m.flags & kConfigFlagApplyAndSave) != 0) apply_config_value(saved_, m.config_type, m.value);
  return Response::kOk;
}

void DeviceControl::on_frame(const Frame& f, FusionEngineWriter& writer, std::vector<std::uint8_t>& out) {
  const std::uint32_t seq = f.header.sequence;
  auto respond = [&](Response code) { writer.append(CommandResponseMessage{seq, static_cast<std::uint8_t>(code)}, out); };
  messages_.dispatch(f.header.message_type, [&](auto& msg) {
    using M = std::decay_t<decltype(msg)>;
    constexpr auto type = M::kType;
    constexpr bool is_command =
        type == MessageType::kSetConfig || type == MessageType::kGetConfig || type == MessageType::kSaveConfig ||
        type == MessageType::kSetMessageRate || type == MessageType::kGetMessageRate ||
        type == MessageType::kResetRequest || type == MessageType::kMessageRequest ||
        type == MessageType::kShutdownRequest || type == MessageType::kStartupRequest ||
        type == MessageType::kFaultControl || type == MessageType::kImportData || type == MessageType::kExportData ||
        type == MessageType::kSta5635Command;
    if constexpr (!is_command) {
      return;  // outputs and sensor inputs are not requests
    } else {
      if (!decode_payload(f.payload, msg)) {
        if constexpr (type == MessageType::kGetConfig) {
          writer.append(ConfigResponseMessage{0, 0, 0, static_cast<std::uint8_t>(Response::kInconsistentPayloadLength), 0, {}}, out);
        } else {
          respond(Response::kInconsistentPayloadLength);
        }
        return;
      }
      if constexpr (type == MessageType::kSetConfig) {
        respond(set_config(msg));
      } else if constexpr (type == MessageType::kGetConfig) {
        ConfigResponseMessage resp;
        resp.source = msg.source;
        resp.config_type = msg.config_type;
        resp.active_differs_from_saved = config_value(active_, msg.config_type) != config_value(saved_, msg.config_type);
        if (auto value = config_value(state_for(msg.source), msg.config_type)) {
          resp.value = std::move(*value);
          resp.response = static_cast<std::uint8_t>(Response::kOk);
        } else {
          resp.response = static_cast<std::uint8_t>(Response::kUnsupportedFeature);  // value omitted (L1615)
        }
        writer.append(resp, out);
      } else if constexpr (type == MessageType::kSaveConfig) {
        switch (static_cast<SaveAction>(msg.action)) {
          case SaveAction::kSave: saved_ = active_; break;
          case SaveAction::kRevertToSaved: active_ = saved_; break;
          // "the same effect as ... ResetRequest with RESET_CONFIG" (L1355).
          case SaveAction::kRevertToDefault: active_ = saved_ = default_; break;
          default: respond(Response::kValueError); return;
        }
        respond(Response::kOk);
      } else if constexpr (type == MessageType::kResetRequest) {
        reset_request_ = msg.reset_mask;
        if ((msg.reset_mask & reset::kResetConfig) != 0) active_ = saved_ = default_;
        respond(Response::kOk);
      } else if constexpr (type == MessageType::kMessageRequest) {
        if (msg.message_type == to_u16(MessageType::kVersionInfo)) {
          VersionInfoMessage v;
          v.fw_version = versions_.firmware;
          v.engine_version = versions_.engine;
          v.os_version = versions_.os;
          v.rx_version = versions_.receiver;
          writer.append(v, out);
        } else {
          respond(Response::kValueError);  // "If the type cannot be requested" (L705)
        }
      } else {
        respond(Response::kUnsupportedFeature);
      }
    }
  });
}

}  // namespace navfuse::frontends::fusionengine

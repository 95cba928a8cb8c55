#include "frontends/mip/commands.hpp"

#include <cmath>
#include <cstdio>

#include "frontends/mip/field_schema.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/packet.hpp"
#include "frontends/mip/writer.hpp"

namespace navfuse::frontends::mip {
namespace {

// Command descriptors (digest §7.1-§7.3).
constexpr std::uint8_t kPing = 0x01, kIdle = 0x02, kDeviceInfo = 0x03, kResume = 0x06, kTimeUpdate = 0x72;
constexpr std::uint8_t kBaseRate = 0x0E, kMessageFormat = 0x0F, kStreamControl = 0x11, kStartupSettings = 0x30,
                       kSensorToVehicleEuler = 0x31;
constexpr std::uint8_t kResetFilter = 0x01, kRunFilter = 0x05, kAidingControl = 0x50, kFilterInit = 0x52,
                       kMultiAntennaOffset = 0x54, kSpeedLeverArm = 0x61;
constexpr std::uint8_t kSpeedSource = 1;  // (0x0D,0x61) source: "reserved, must be 1" (L8688)
constexpr std::uint8_t kTimeFieldWeek = 1, kTimeFieldTow = 2;  // (0x01,0x72) field_id (L8160)
constexpr std::uint8_t kAutoPosVelAtt = 0;                     // (0x0D,0x52) initial_cond_src
constexpr std::uint8_t kLlhFrame = 2;                          // reference_frame_selector

FieldValue u(std::uint64_t v) { return FieldValue{v}; }
FieldValue d(double v) { return FieldValue{v}; }
FieldValue fn(Function f) { return u(static_cast<std::uint64_t>(f)); }

std::uint16_t decimation(double base_hz, double rate_hz) {
  if (!(rate_hz > 0.0) || !(base_hz > 0.0)) return 1;
  const double dec = std::round(base_hz / rate_hz);
  return static_cast<std::uint16_t>(std::clamp(dec, 1.0, 65535.0));
}

}  // namespace

std::optional<std::vector<std::uint8_t>> build_command_packet(std::span<const Command> commands) {
  if (commands.empty()) return std::nullopt;
  std::vector<std::uint8_t> out;
  std::vector<std::uint8_t> data;
  PacketWriter pw(out, commands[0].desc_set);
  for (const auto& c : commands) {
    if (c.desc_set != commands[0].desc_set) return std::nullopt;
    data.clear();
    bytes::BeWriter w(data);
    if (!c.values.empty()) {
      // The variant of a layout (trigger type, frame format...) is read from the encoded bytes:
      // encode with the first matching schema, then check the bytes select the same one.
      const FieldSchema* s = nullptr;
      for (const auto& cand : command_schemas()) {
        if (cand.set != c.desc_set || cand.desc != c.desc) continue;
        data.clear();
        if (encode_values(cand, c.values, w) && find_schema(c.desc_set, c.desc, data) == &cand) {
          s = &cand;
          break;
        }
      }
      if (s == nullptr) return std::nullopt;
    }
    if (data.size() > kMaxFieldData) return std::nullopt;
    pw.raw_field(c.desc, data);
  }
  pw.finish();
  return out;
}

std::optional<std::vector<std::uint8_t>> build_command_packet(const Command& command) {
  return build_command_packet(std::span<const Command>(&command, 1));
}

Command ping() { return {set::kBase, kPing, {}}; }
Command set_idle() { return {set::kBase, kIdle, {}}; }
Command resume() { return {set::kBase, kResume, {}}; }
Command get_device_info() { return {set::kBase, kDeviceInfo, {}}; }
Command get_base_rate(std::uint8_t data_set) { return {set::k3dm, kBaseRate, {u(data_set)}}; }

Command message_format(std::uint8_t data_set, std::span<const DescriptorRate> fields) {
  Command c{set::k3dm, kMessageFormat, {fn(Function::kWrite), u(data_set), u(fields.size())}};
  for (const auto& f : fields) {
    c.values.push_back(u(f.descriptor));
    c.values.push_back(u(f.decimation));
  }
  return c;
}

Command stream_enable(std::uint8_t data_set, bool enable) {
  return {set::k3dm, kStreamControl, {fn(Function::kWrite), u(data_set), u(enable ? 1 : 0)}};
}

Command save_all_settings() { return {set::k3dm, kStartupSettings, {fn(Function::kSave)}}; }

Command sensor_to_vehicle_euler(const Eigen::Vector3d& rpy_rad) {
  return {set::k3dm, kSensorToVehicleEuler, {fn(Function::kWrite), d(rpy_rad.x()), d(rpy_rad.y()), d(rpy_rad.z())}};
}

Command antenna_offset(std::uint8_t receiver_id, const Eigen::Vector3d& offset_m) {
  return {set::kFilterCmd, kMultiAntennaOffset,
          {fn(Function::kWrite), u(receiver_id), d(offset_m.x()), d(offset_m.y()), d(offset_m.z())}};
}

Command speed_lever_arm(const Eigen::Vector3d& offset_m) {
  return {set::kFilterCmd, kSpeedLeverArm,
          {fn(Function::kWrite), u(kSpeedSource), d(offset_m.x()), d(offset_m.y()), d(offset_m.z())}};
}

Command read_of(const Command& write, std::size_t key_params) {
  Command read{write.desc_set, write.desc, {fn(Function::kRead)}};
  for (std::size_t i = 1; i <= key_params && i < write.values.size(); ++i) read.values.push_back(write.values[i]);
  return read;
}

Command aiding_control(std::uint16_t aiding_source, bool enable) {
  return {set::kFilterCmd, kAidingControl, {fn(Function::kWrite), u(aiding_source), u(enable ? 1 : 0)}};
}

Command reset_filter() { return {set::kFilterCmd, kResetFilter, {}}; }
Command run_filter() { return {set::kFilterCmd, kRunFilter, {}}; }

Command filter_init_auto(std::uint8_t heading_alignment_bits) {
  Command c{set::kFilterCmd, kFilterInit, {fn(Function::kWrite), u(0), u(kAutoPosVelAtt), u(heading_alignment_bits)}};
  for (int i = 0; i < 9; ++i) c.values.push_back(d(0.0));  // heading, pitch, roll, position, velocity
  c.values.push_back(u(kLlhFrame));
  return c;
}

Command gps_time_update(bool week, std::uint32_t value) {
  return {set::kBase, kTimeUpdate, {fn(Function::kWrite), u(week ? kTimeFieldWeek : kTimeFieldTow), u(value)}};
}

std::vector<std::vector<std::uint8_t>> cv7_setup_sequence(const SetupOptions& o) {
  std::vector<std::vector<std::uint8_t>> seq;
  auto add = [&](const Command& c) {
    if (auto p = build_command_packet(c)) seq.push_back(std::move(*p));
  };
  add(set_idle());
  const std::uint16_t imu = decimation(o.sensor_base_rate_hz, o.imu_rate_hz);
  const DescriptorRate sensor_fields[] = {{shared::kGpsTimestamp, imu}, {shared::kReferenceTimestamp, imu},
                                          {sensor::kDeltaTheta, imu}, {sensor::kDeltaVelocity, imu}};
  add(message_format(set::kSensor, sensor_fields));
  const std::uint16_t gnss_dec = decimation(o.gnss_base_rate_hz, o.gnss_rate_hz);
  const DescriptorRate gnss_fields[] = {{shared::kGpsTimestamp, gnss_dec}, {gnss::kLlh, gnss_dec},
                                        {gnss::kVelNed, gnss_dec}, {gnss::kFixInfo, gnss_dec}};
  add(message_format(set::kGnss1, gnss_fields));
  if (o.second_receiver) add(message_format(set::kGnss2, gnss_fields));
  const std::uint16_t f = decimation(o.filter_base_rate_hz, o.filter_rate_hz);
  const DescriptorRate filter_fields[] = {{shared::kGpsTimestamp, f}, {filter::kStatus, f}, {filter::kLlh, f},
                                          {filter::kVelNed, f},        {filter::kEuler, f},  {filter::kLlhUnc, f},
                                          {filter::kVelUnc, f},        {filter::kEulerUnc, f}};
  add(message_format(set::kFilter, filter_fields));
  add(stream_enable(set::kSensor, true));
  add(stream_enable(set::kGnss1, true));
  if (o.second_receiver) add(stream_enable(set::kGnss2, true));
  add(stream_enable(set::kFilter, true));
  add(resume());
  return seq;
}

bool parse_reply(std::span<const std::uint8_t> payload, std::vector<ReplyEntry>& out) {
  out.clear();
  FieldWalker walk(payload);
  FieldView f;
  while (walk.next(f)) {
    if (f.desc == kAckNackDescriptor) {
      if (f.data.size() < 2) return false;
      ReplyEntry e;
      e.cmd_desc = f.data[0];
      e.code = static_cast<ReplyCode>(f.data[1]);
      out.push_back(std::move(e));
    } else if (!out.empty() && !out.back().response_desc) {
      out.back().response_desc = f.desc;  // response data follows its ACK (L3852)
      out.back().response_data.assign(f.data.begin(), f.data.end());
    }
  }
  return !walk.malformed();
}

std::string find_refusal(std::span<const std::uint8_t> reply_bytes) {
  Framer framer;
  std::string refusal;
  std::vector<ReplyEntry> entries;
  framer.feed(reply_bytes, [&](const PacketView& p) {
    if (!refusal.empty() || !set::is_command(p.desc_set)) return;
    entries.clear();
    if (!parse_reply(p.payload, entries)) return;
    for (const auto& e : entries) {
      if (e.code != ReplyCode::kAck) {
        char text[64];
        std::snprintf(text, sizeof text, "MIP NACK %u for command (0x%02X,0x%02X)",
                      static_cast<unsigned>(e.code), p.desc_set, e.cmd_desc);
        refusal = text;
        return;
      }
    }
  });
  return refusal;
}

}  // namespace navfuse::frontends::mip

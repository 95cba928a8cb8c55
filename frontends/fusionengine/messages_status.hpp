// Status, version, event, device ID, corrections and platform messages (spec §3.7, §3.8,
// §3.10, digest §8).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

// SystemStatus 10500, 128 bytes (spec §3.7.1 L2473-2486). Upstream v1.25.0 (version 1) puts a
// processor temperature at offset 10 inside the spec's reserved bytes; it is read and written
// here (reserved bytes are 0 in version 0, so version-0 senders read as 0, not invalid).
struct SystemStatusMessage {
  static constexpr MessageType kType = MessageType::kSystemStatus;
  static constexpr std::uint8_t kVersion = 1;
  static constexpr std::string_view kName = "SystemStatus";
  static constexpr std::size_t kSize = 128;
  Timestamp p1_time;
  std::int16_t gnss_temperature = 0x7FFF;  // deg C * 2^-7, 0x7FFF invalid (L2485)
  std::int16_t pe_cpu_temperature = 0x7FFF;
  template <class V>
  void visit(V& v) {
    v.timestamp("p1_time", p1_time);
    v.field("gnss_temperature_2^-7degc", gnss_temperature);
    v.field("cpu_temperature_2^-7degc", pe_cpu_temperature);
    v.reserved(116);
  }
};

// SSRStatus 10501, 96 bytes (spec §3.7.2 L2490-2584). Not in the public client (digest §8.2).
struct SsrStatusMessage {
  static constexpr MessageType kType = MessageType::kSsrStatus;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "SSRStatus";
  static constexpr std::size_t kSize = 96;
  std::int64_t system_time_ns = 0;
  std::uint16_t gps_week = 0;
  std::uint32_t gps_tow = 0;  // "in ns" per L2504, which overflows; probably ms (digest B20)
  Timestamp output_gps_time;
  std::uint8_t output_source = 0;
  std::uint16_t station_id = 0xFFFF;
  std::array<double, 3> base_lla{};  // deg, deg, m
  std::uint8_t num_satellites = 0, num_signals = 0;
  std::array<std::uint16_t, 5> system_and_signal_masks{};  // systems, GPS, GLO, GAL, BDS
  std::array<std::uint8_t, 4> num_ephemeris{};  // GPS, GLO, GAL, BDS
  std::uint16_t osr_status = 0, ssr_status = 0;
  std::uint8_t ssr_grid_id = 0xFF;
  std::uint16_t ssr_enabled = 0, ssr_model_status = 0, ssr_decode_status = 0;
  template <class V>
  void visit(V& v) {
    v.field("system_time_ns", system_time_ns);
    v.reserved(2);
    v.field("gps_week", gps_week);
    v.field("gps_tow", gps_tow);
    v.timestamp("output_gps_time", output_gps_time);
    v.field("output_source", output_source);
    v.reserved(1);
    v.field("station_id", station_id);
    v.field("base_lat_deg", base_lla[0]);
    v.field("base_lon_deg", base_lla[1]);
    v.field("base_alt_m", base_lla[2]);
    v.field("num_satellites", num_satellites);
    v.field("num_signals", num_signals);
    v.field("gnss_systems_mask", system_and_signal_masks[0]);
    v.field("gps_signals_mask", system_and_signal_masks[1]);
    v.field("glo_signals_mask", system_and_signal_masks[2]);
    v.field("gal_signals_mask", system_and_signal_masks[3]);
    v.field("bds_signals_mask", system_and_signal_masks[4]);
    v.reserved(8);
    v.field("num_gps_ephemeris", num_ephemeris[0]);
    v.field("num_glo_ephemeris", num_ephemeris[1]);
    v.field("num_gal_ephemeris", num_ephemeris[2]);
    v.field("num_bds_ephemeris", num_ephemeris[3]);
    v.reserved(4);
    v.field("osr_status", osr_status);
    v.reserved(2);
    v.field("ssr_status", ssr_status);
    v.reserved(1);
    v.field("ssr_grid_id", ssr_grid_id);
    v.field("ssr_enabled_components", ssr_enabled);
    v.field("ssr_model_status", ssr_model_status);
    v.field("ssr_decode_status", ssr_decode_status);
    v.reserved(2);
  }
};

// VersionInfoMessage 13003, 16 + strings, "padded to a length that is a multiple of 4 bytes"
// (spec §3.7.3 L2588-2611). The padding is part of the payload; readers ignore it.
struct VersionInfoMessage {
  static constexpr MessageType kType = MessageType::kVersionInfo;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "VersionInfo";
  static constexpr std::size_t kSize = 16;
  std::int64_t system_time_ns = 0;
  std::uint8_t fw_length = 0, engine_length = 0, os_length = 0, rx_length = 0;
  std::string fw_version, engine_version, os_version, rx_version;
  void sync_lengths() {
    fw_length = clamp_length(fw_version);
    engine_length = clamp_length(engine_version);
    os_length = clamp_length(os_version);
    rx_length = clamp_length(rx_version);
  }
  // Bytes of zero padding after the strings to reach a multiple of 4 (L2611).
  std::size_t padding() const {
    const std::size_t n = kSize + fw_length + engine_length + os_length + rx_length;
    return (4 - n % 4) % 4;
  }
  template <class V>
  void visit(V& v) {
    v.field("system_time_ns", system_time_ns);
    v.field("fw_version_length", fw_length);
    v.field("engine_version_length", engine_length);
    v.field("os_version_length", os_length);
    v.field("rx_version_length", rx_length);
    v.reserved(4);
    v.text("fw_version", fw_version, fw_length);
    v.text("engine_version", engine_version, engine_length);
    v.text("os_version", os_version, os_length);
    v.text("rx_version", rx_version, rx_length);
  }

 private:
  static std::uint8_t clamp_length(const std::string& s) {
    return static_cast<std::uint8_t>(s.size() > 255 ? 255 : s.size());
  }
};

// EventNotificationMessage 13004 (spec §3.7.4 L2615-2642). The spec has no reserved bytes after
// the description length (string at 22); upstream has two, so the string starts at 24
// (digest §13 A5).
enum class EventType : std::uint8_t { kLog = 0, kReset = 1, kConfigChange = 2, kCommand = 3, kCommandResponse = 4 };
struct EventNotificationMessage {
  static constexpr MessageType kType = MessageType::kEventNotification;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "EventNotification";
  static constexpr std::size_t kSize = 24;
  std::uint8_t event_type = 0;
  std::int64_t system_time_ns = 0;
  std::uint64_t event_flags = 0;
  std::uint16_t description_length = 0;
  std::string description;
  void sync_lengths() {
    if (description.size() > 0xFFFF) description.resize(0xFFFF);
    description_length = static_cast<std::uint16_t>(description.size());
  }
  template <class V>
  void visit(V& v) {
    v.field("event_type", event_type);
    v.reserved(3);
    v.field("system_time_ns", system_time_ns);
    v.field("event_flags", event_flags);
    v.field("description_length", description_length);
    v.reserved(2);
    v.text("description", description, description_length);
  }
};

// DeviceIDMessage 13007, 16 + x + y + z (spec §3.7.5 L2646-2677).
struct DeviceIdMessage {
  static constexpr MessageType kType = MessageType::kDeviceId;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "DeviceID";
  static constexpr std::size_t kSize = 16;
  std::int64_t system_time_ns = 0;
  std::uint8_t device_type = 0;
  std::uint8_t hw_id_length = 0, user_id_length = 0, gnss_id_length = 0;
  std::vector<std::uint8_t> hw_id, user_id, gnss_id;
  void sync_lengths() {
    hw_id_length = static_cast<std::uint8_t>(hw_id.size() > 255 ? 255 : hw_id.size());
    user_id_length = static_cast<std::uint8_t>(user_id.size() > 255 ? 255 : user_id.size());
    gnss_id_length = static_cast<std::uint8_t>(gnss_id.size() > 255 ? 255 : gnss_id.size());
  }
  template <class V>
  void visit(V& v) {
    v.field("system_time_ns", system_time_ns);
    v.field("device_type", device_type);
    v.field("hw_id_length", hw_id_length);
    v.field("user_id_length", user_id_length);
    v.field("gnss_id_length", gnss_id_length);
    v.reserved(4);
    v.blob("hw_id", hw_id, hw_id_length);
    v.blob("user_id", user_id, user_id_length);
    v.blob("gnss_id", gnss_id, gnss_id_length);
  }
};

// LBandFrameMessage 14000, 20 + n (spec §3.8.1 L2687-2704).
struct LBandFrameMessage {
  static constexpr MessageType kType = MessageType::kLBandFrame;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "LBandFrame";
  static constexpr std::size_t kSize = 20;
  std::int64_t system_time_ns = 0;
  std::uint16_t user_data_size = 0;
  std::uint16_t bit_error_count = 0;
  std::uint8_t signal_power_db = 0;
  float doppler_hz = 0;
  std::vector<std::uint8_t> data;
  void sync_lengths() { user_data_size = static_cast<std::uint16_t>(data.size() > 0xFFFF ? 0xFFFF : data.size()); }
  template <class V>
  void visit(V& v) {
    v.field("system_time_ns", system_time_ns);
    v.field("user_data_size", user_data_size);
    v.field("bit_error_count", bit_error_count);
    v.field("signal_power_db", signal_power_db);
    v.reserved(3);
    v.field("doppler_hz", doppler_hz);
    v.blob("data", data, user_data_size);
  }
};

// STA5635 RF front-end messages (spec §3.10, L2834-2886).
struct Sta5635CommandMessage {
  static constexpr MessageType kType = MessageType::kSta5635Command;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "STA5635Command";
  static constexpr std::size_t kSize = 4;
  std::uint8_t command = 0, address = 0;
  std::array<std::uint8_t, 2> data{};
  template <class V>
  void visit(V& v) {
    v.field("command", command);
    v.field("address", address);
    v.array("data", data);
  }
};
struct Sta5635CommandResponseMessage {
  static constexpr MessageType kType = MessageType::kSta5635CommandResponse;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "STA5635CommandResponse";
  static constexpr std::size_t kSize = 16;
  std::int64_t system_time_ns = 0;
  std::uint32_t command_sequence = 0;  // the spec's description is copy-pasted (digest B24)
  std::array<std::uint8_t, 4> data{};
  template <class V>
  void visit(V& v) {
    v.field("system_time_ns", system_time_ns);
    v.field("command_sequence", command_sequence);
    v.array("data", data);
  }
};
struct Sta5635IqDataMessage {
  static constexpr MessageType kType = MessageType::kSta5635IqData;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "STA5635IQData";
  static constexpr std::size_t kSize = 4;
  static constexpr std::size_t kMaxVariableSize = kMaxOpaqueDataSize;  // "the rest of the payload"
  std::vector<std::uint8_t> samples;
  template <class V>
  void visit(V& v) {
    v.reserved(4);
    v.rest("samples", samples);
  }
};

}  // namespace navfuse::frontends::fusionengine

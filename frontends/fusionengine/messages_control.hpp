// Command, configuration, rate-control and response messages (spec §3.1-3.2, digest §7).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

// CommandResponseMessage 13000, 8 bytes (spec §3.2.1 L1562-1590).
struct CommandResponseMessage {
  static constexpr MessageType kType = MessageType::kCommandResponse;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "CommandResponse";
  static constexpr std::size_t kSize = 8;
  std::uint32_t source_sequence = 0;  // sequence number of the command answered
  std::uint8_t response = 0;          // Response
  template <class V>
  void visit(V& v) {
    v.field("source_sequence", source_sequence);
    v.field("response", response);
    v.reserved(3);
  }
};

// MessageRequest 13001, 4 bytes (spec §3.1.1 L694-715).
struct MessageRequestMessage {
  static constexpr MessageType kType = MessageType::kMessageRequest;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "MessageRequest";
  static constexpr std::size_t kSize = 4;
  std::uint16_t message_type = 0;
  template <class V>
  void visit(V& v) {
    v.field("message_type", message_type);
    v.reserved(2);
  }
};

// ResetRequest 13002, 4 bytes (spec §3.1.2 L719-798).
namespace reset {
inline constexpr std::uint32_t kRestartNavigationEngine = 1u << 0;
inline constexpr std::uint32_t kResetGnssCorrections = 1u << 1;
inline constexpr std::uint32_t kResetGnssTime = 1u << 2;
inline constexpr std::uint32_t kResetPositionData = 1u << 8;
inline constexpr std::uint32_t kResetEphemeris = 1u << 9;
inline constexpr std::uint32_t kResetFastImuCorrections = 1u << 10;
inline constexpr std::uint32_t kResetNavigationEngineData = 1u << 12;
inline constexpr std::uint32_t kResetCalibrationData = 1u << 13;
inline constexpr std::uint32_t kResetConfig = 1u << 20;
inline constexpr std::uint32_t kRebootGnssMeasurementEngine = 1u << 24;
inline constexpr std::uint32_t kRebootNavigationProcessor = 1u << 25;
inline constexpr std::uint32_t kDiagnosticLogReset = 1u << 26;
// Special masks (L758-774). COLD_START is 0x00000FFF as the table (L770) and upstream say;
// the hex example at L788 carries 0x01000FFF (cold start + GNSS engine reboot), which is used
// only as a framing vector (digest §13 A7).
inline constexpr std::uint32_t kHotStart = 0x00000001;
inline constexpr std::uint32_t kWarmStart = 0x00000201;
inline constexpr std::uint32_t kColdStart = 0x00000FFF;
inline constexpr std::uint32_t kPoseReset = 0x000001FB;
inline constexpr std::uint32_t kFactoryReset = 0xFFFFFFFF;
}  // namespace reset
struct ResetRequestMessage {
  static constexpr MessageType kType = MessageType::kResetRequest;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "ResetRequest";
  static constexpr std::size_t kSize = 4;
  std::uint32_t reset_mask = 0;
  template <class V>
  void visit(V& v) {
    v.field("reset_mask", reset_mask);
  }
};

// ShutdownRequest 13005 (L802-835) and StartupRequest 13008 (L912-935): u64 flags + 8 reserved.
struct ShutdownRequestMessage {
  static constexpr MessageType kType = MessageType::kShutdownRequest;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "ShutdownRequest";
  static constexpr std::size_t kSize = 16;
  std::uint64_t flags = 0;  // 0 is treated as "stop engine" (L822)
  template <class V>
  void visit(V& v) {
    v.field("flags", flags);
    v.reserved(8);
  }
};
struct StartupRequestMessage {
  static constexpr MessageType kType = MessageType::kStartupRequest;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "StartupRequest";
  static constexpr std::size_t kSize = 16;
  std::uint64_t flags = 0;
  template <class V>
  void visit(V& v) {
    v.field("flags", flags);
    v.reserved(8);
  }
};

// FaultControl 13006, 20 + len bytes (spec §3.1.4 L839-908). Example E5 (L889-894) is 45 bytes:
// payload sizes need not be multiples of 4 (digest §13 A1).
struct FaultControlMessage {
  static constexpr MessageType kType = MessageType::kFaultControl;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "FaultControl";
  static constexpr std::size_t kSize = 20;
  // The u32 Value Length could claim 4 GiB; every fault type's value is None, a u8 or a bool
  // (L859-870), so one byte.
  static constexpr std::size_t kMaxVariableSize = 1;
  std::uint8_t fault_type = 0;
  std::uint32_t value_length = 0;
  std::vector<std::uint8_t> value;
  void sync_lengths() { value_length = static_cast<std::uint32_t>(value.size()); }
  template <class V>
  void visit(V& v) {
    v.field("fault_type", fault_type);
    v.reserved(15);
    v.field("value_length", value_length);
    v.blob("value", value, value_length);
  }
};

// SetConfigMessage 13100, 8 + len bytes (spec §3.1.6 L939-1037).
inline constexpr std::uint8_t kConfigFlagApplyAndSave = 0x01;
inline constexpr std::uint8_t kConfigFlagRevertToDefault = 0x02;
struct SetConfigMessage {
  static constexpr MessageType kType = MessageType::kSetConfig;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "SetConfig";
  static constexpr std::size_t kSize = 8;
  static constexpr std::size_t kMaxVariableSize = kMaxConfigValueSize;  // u32 Value Length
  std::uint16_t config_type = 0;
  std::uint8_t flags = 0;
  std::uint32_t value_length = 0;
  std::vector<std::uint8_t> value;
  void sync_lengths() { value_length = static_cast<std::uint32_t>(value.size()); }
  template <class V>
  void visit(V& v) {
    v.field("config_type", config_type);
    v.field("flags", flags);
    v.reserved(1);
    v.field("value_length", value_length);
    v.config_value("value", config_type, value, value_length);
  }
};

// Configuration source (L1324-1328); upstream also has 2 = DEFAULT (digest §4.11).
enum class ConfigSource : std::uint8_t { kActive = 0, kSaved = 1, kDefault = 2 };

// GetConfigMessage 13101, 4 bytes (spec §3.1.7 L1309-1332).
struct GetConfigMessage {
  static constexpr MessageType kType = MessageType::kGetConfig;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "GetConfig";
  static constexpr std::size_t kSize = 4;
  std::uint16_t config_type = 0;
  std::uint8_t source = 0;
  template <class V>
  void visit(V& v) {
    v.field("config_type", config_type);
    v.field("config_source", source);
    v.reserved(1);
  }
};

// SaveConfigMessage 13102, 4 bytes (spec §3.1.8 L1336-1377).
enum class SaveAction : std::uint8_t { kSave = 0, kRevertToSaved = 1, kRevertToDefault = 2 };
struct SaveConfigMessage {
  static constexpr MessageType kType = MessageType::kSaveConfig;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "SaveConfig";
  static constexpr std::size_t kSize = 4;
  std::uint8_t action = 0;
  template <class V>
  void visit(V& v) {
    v.field("action", action);
    v.reserved(3);
  }
};

// ConfigResponseMessage 13103, 12 + len bytes (spec §3.2.2 L1594-1622). Byte 1 is "Active
// Differs From Saved" (upstream: flags bit 0; compatible, digest §13 B31).
struct ConfigResponseMessage {
  static constexpr MessageType kType = MessageType::kConfigResponse;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "ConfigResponse";
  static constexpr std::size_t kSize = 12;
  static constexpr std::size_t kMaxVariableSize = kMaxConfigValueSize;  // u32 Value Length
  std::uint8_t source = 0;
  std::uint8_t active_differs_from_saved = 0;
  std::uint16_t config_type = 0;
  std::uint8_t response = 0;
  std::uint32_t value_length = 0;
  std::vector<std::uint8_t> value;
  void sync_lengths() { value_length = static_cast<std::uint32_t>(value.size()); }
  template <class V>
  void visit(V& v) {
    v.field("config_source", source);
    v.field("active_differs_from_saved", active_differs_from_saved);
    v.field("config_type", config_type);
    v.field("response", response);
    v.reserved(3);
    v.field("value_length", value_length);
    v.config_value("value", config_type, value, value_length);
  }
};

// DataVersion is a 4-byte struct (L621-631); ImportData / PlatformStorageData call it "(u16)",
// the 4-byte struct is used (digest §13 A4).
struct DataVersion {
  static constexpr std::size_t kSize = 4;
  std::uint8_t reserved = 0xFF;  // "Must be set to 0xFF" (L629)
  std::uint8_t major = 0xFF;
  std::uint16_t minor = kInvalidU16Version;
  static constexpr std::uint16_t kInvalidU16Version = 0xFFFF;
  template <class V>
  void visit(V& v) {
    v.field("data_version_reserved", reserved);
    v.field("data_version_major", major);
    v.field("data_version_minor", minor);
  }
};

// ImportDataMessage 13110 (L1381-1398), 16 + len with the 4-byte DataVersion.
struct ImportDataMessage {
  static constexpr MessageType kType = MessageType::kImportData;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "ImportData";
  static constexpr std::size_t kSize = 16;
  static constexpr std::size_t kMaxVariableSize = kMaxOpaqueDataSize;  // u32 Data Length
  std::uint8_t data_type = 0;
  std::uint8_t source = 0;
  DataVersion version;
  std::uint32_t data_length = 0;
  std::vector<std::uint8_t> data;
  void sync_lengths() { data_length = static_cast<std::uint32_t>(data.size()); }
  template <class V>
  void visit(V& v) {
    v.field("data_type", data_type);
    v.field("config_source", source);
    v.reserved(2);
    version.visit(v);
    v.reserved(4);
    v.field("data_length", data_length);
    v.blob("data", data, data_length);
  }
};

// ExportDataMessage 13111, 4 bytes (L1402-1415; the body's "13222" is a typo, digest §13 B10).
struct ExportDataMessage {
  static constexpr MessageType kType = MessageType::kExportData;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "ExportData";
  static constexpr std::size_t kSize = 4;
  std::uint8_t data_type = 0;
  std::uint8_t source = 0;
  template <class V>
  void visit(V& v) {
    v.field("data_type", data_type);
    v.field("config_source", source);
    v.reserved(2);
  }
};

// PlatformStorageDataMessage 13113, version 3 (L1625-1651), 12 + len with 4-byte DataVersion.
struct PlatformStorageDataMessage {
  static constexpr MessageType kType = MessageType::kPlatformStorageData;
  static constexpr std::uint8_t kVersion = 3;
  static constexpr std::string_view kName = "PlatformStorageData";
  static constexpr std::size_t kSize = 12;
  static constexpr std::size_t kMaxVariableSize = kMaxOpaqueDataSize;  // u32 Data Length
  std::uint8_t data_type = 0;
  std::uint8_t response = 0;
  std::uint8_t source = 0;
  std::uint8_t flags = 0;
  DataVersion version;
  std::uint32_t data_length = 0;
  std::vector<std::uint8_t> data;
  void sync_lengths() { data_length = static_cast<std::uint32_t>(data.size()); }
  template <class V>
  void visit(V& v) {
    v.field("data_type", data_type);
    v.field("response", response);
    v.field("config_source", source);
    v.field("flags", flags);
    version.visit(v);
    v.field("data_length", data_length);
    v.blob("data", data, data_length);
  }
};

// Message rate control (spec §3.1.11-3.1.12, §3.2.4, L1419-1690).
enum class ProtocolType : std::uint8_t { kInvalid = 0, kFusionEngine = 1, kNmea = 2, kRtcm = 3, kAll = 0xFF };
enum class MessageRate : std::uint8_t {
  kOff = 0, kOnChange = 1, k10Ms = 2, k20Ms = 3, k40Ms = 4, k50Ms = 5, k100Ms = 6, k200Ms = 7,
  k500Ms = 8, k1S = 9, k2S = 10, k5S = 11, k10S = 12, k30S = 13, k60S = 14, kDefault = 0xFF,
};
// Output interval of an interval rate (spec L1464-1482), seconds; 0 for Off, On Change, Default.
constexpr double interval_s(MessageRate r) {
  switch (r) {
    case MessageRate::k10Ms: return 0.01;
    case MessageRate::k20Ms: return 0.02;
    case MessageRate::k40Ms: return 0.04;
    case MessageRate::k50Ms: return 0.05;
    case MessageRate::k100Ms: return 0.1;
    case MessageRate::k200Ms: return 0.2;
    case MessageRate::k500Ms: return 0.5;
    case MessageRate::k1S: return 1;
    case MessageRate::k2S: return 2;
    case MessageRate::k5S: return 5;
    case MessageRate::k10S: return 10;
    case MessageRate::k30S: return 30;
    case MessageRate::k60S: return 60;
    default: return 0;
  }
}
// Whether a rate byte of a command is one of the MessageRate values.
constexpr bool valid_rate(std::uint8_t r) { return r <= static_cast<std::uint8_t>(MessageRate::k60S) || r == 0xFF; }
inline constexpr std::uint16_t kAllMessages = 0xFFFF;
inline constexpr std::uint8_t kRateFlagApplyAndSave = 0x01;
inline constexpr std::uint8_t kRateFlagIncludeDisabled = 0x02;  // four spellings, digest §13 B11
// MessageRateResponse entry flags (spec L1683-1685).
inline constexpr std::uint8_t kRateEntryActiveDiffersFromSaved = 0x01;

struct SetMessageRateMessage {
  static constexpr MessageType kType = MessageType::kSetMessageRate;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "SetMessageRate";
  static constexpr std::size_t kSize = 12;
  InterfaceId output_interface;
  std::uint8_t protocol = 0;
  std::uint8_t flags = 0;
  std::uint16_t message_id = 0;
  std::uint8_t rate = 0;
  template <class V>
  void visit(V& v) {
    output_interface.visit(v);
    v.field("protocol", protocol);
    v.field("flags", flags);
    v.field("message_id", message_id);
    v.field("rate", rate);
    v.reserved(3);
  }
};

struct GetMessageRateMessage {
  static constexpr MessageType kType = MessageType::kGetMessageRate;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "GetMessageRate";
  static constexpr std::size_t kSize = 8;
  InterfaceId output_interface;
  std::uint8_t protocol = 0;
  std::uint8_t source = 0;
  std::uint16_t message_id = 0;
  template <class V>
  void visit(V& v) {
    output_interface.visit(v);
    v.field("protocol", protocol);
    v.field("config_source", source);
    v.field("message_id", message_id);
  }
};

struct MessageRateEntry {
  static constexpr std::size_t kSize = 8;
  std::uint8_t protocol = 0;
  std::uint8_t flags = 0;  // bit 0: active differs from saved
  std::uint16_t message_id = 0;
  std::uint8_t configured_rate = 0;
  std::uint8_t effective_rate = 0;
  template <class V>
  void visit(V& v) {
    v.field("protocol", protocol);
    v.field("flags", flags);
    v.field("message_id", message_id);
    v.field("configured_rate", configured_rate);
    v.field("effective_rate", effective_rate);
    v.reserved(2);
  }
};
struct MessageRateResponseMessage {
  static constexpr MessageType kType = MessageType::kMessageRateResponse;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "MessageRateResponse";
  static constexpr std::size_t kSize = 8;
  std::uint8_t source = 0;
  std::uint8_t response = 0;
  std::uint16_t num_rates = 0;
  InterfaceId output_interface;
  std::vector<MessageRateEntry> rates;
  void sync_lengths() { num_rates = static_cast<std::uint16_t>(rates.size()); }
  template <class V>
  void visit(V& v) {
    v.field("config_source", source);
    v.field("response", response);
    v.field("num_rates", num_rates);
    output_interface.visit(v);
    v.list("rate", rates, num_rates);
  }
};

// SupportedIOInterfacesMessage 13223, 8 + 4 N bytes (spec §3.2.5 L1694-1711).
struct SupportedIoInterfacesMessage {
  static constexpr MessageType kType = MessageType::kSupportedIoInterfaces;
  static constexpr std::uint8_t kVersion = 0;
  static constexpr std::string_view kName = "SupportedIOInterfaces";
  static constexpr std::size_t kSize = 8;
  std::uint8_t num_interfaces = 0;
  std::vector<InterfaceId> interfaces;
  void sync_lengths() { num_interfaces = static_cast<std::uint8_t>(interfaces.size()); }
  template <class V>
  void visit(V& v) {
    v.field("num_interfaces", num_interfaces);
    v.reserved(7);
    v.list("if", interfaces, num_interfaces);
  }
};

}  // namespace navfuse::frontends::fusionengine

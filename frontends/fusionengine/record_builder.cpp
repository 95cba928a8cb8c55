#include "frontends/fusionengine/record_builder.hpp"

#include <span>

#include "frontends/fusionengine/config_types.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

// Hex of at most this many bytes: blobs (raw wrapped data, IQ samples) can be large and the
// record is for reading, not for reconstructing them.
constexpr std::size_t kMaxHexBytes = 64;

std::string hex(std::span<const std::uint8_t> b) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s;
  const std::size_t n = b.size() < kMaxHexBytes ? b.size() : kMaxHexBytes;
  s.reserve(2 * n + 3);
  for (std::size_t i = 0; i < n; ++i) {
    s += kDigits[b[i] >> 4];
    s += kDigits[b[i] & 0xF];
  }
  if (n < b.size()) s += "...";
  return s;
}

// Lists a typed config value's fields under "<name>_" when it parses.
template <class C>
bool add_config(RecordBuilder& rb, std::span<const std::uint8_t> bytes) {
  auto value = parse_config<C>(bytes);
  if (!value) return false;
  value->visit(rb);
  return true;
}

}  // namespace

void RecordBuilder::timestamp(std::string_view name, const Timestamp& t) {
  std::string key = std::string(name) + "_ns";
  if (t.valid()) {
    add(key, t.ns());
  } else {
    add(key, std::string("invalid"));
  }
}

void RecordBuilder::blob(std::string_view name, const std::vector<std::uint8_t>& b, std::size_t) {
  add(std::string(name) + "_hex", hex(b));
}

void RecordBuilder::config_value(std::string_view name, std::uint16_t config_type,
                                 const std::vector<std::uint8_t>& b, std::size_t length) {
  add("config_name", std::string(to_string(static_cast<ConfigType>(config_type))));
  const std::string saved = prefix_;
  prefix_ += std::string(name) + "_";
  bool listed = false;
  switch (static_cast<ConfigType>(config_type)) {
    case ConfigType::kDeviceLeverArm:
    case ConfigType::kGnssLeverArm:
    case ConfigType::kOutputLeverArm:
    case ConfigType::kGnssAuxLeverArm:
      listed = add_config<Point3f>(*this, b);
      break;
    case ConfigType::kDeviceCoarseOrientation: listed = add_config<CoarseOrientation>(*this, b); break;
    case ConfigType::kVehicleDetails: listed = add_config<VehicleDetails>(*this, b); break;
    case ConfigType::kWheelConfig: listed = add_config<WheelConfig>(*this, b); break;
    case ConfigType::kHardwareTickConfig: listed = add_config<HardwareTickConfig>(*this, b); break;
    case ConfigType::kEnabledGnssSystems:
    case ConfigType::kEnabledGnssFrequencyBands:
    case ConfigType::kUart1BaudRate:
    case ConfigType::kUart2BaudRate:
      listed = add_config<ScalarConfig<std::uint32_t>>(*this, b);
      break;
    case ConfigType::kLeapSecond:
    case ConfigType::kGpsWeekRollover:
      listed = add_config<ScalarConfig<std::int32_t>>(*this, b);
      break;
    case ConfigType::kUart1OutputDiagnostics:
    case ConfigType::kUart2OutputDiagnostics:
    case ConfigType::kEnableWatchdogTimer:
    case ConfigType::kProfilingMask:
      listed = add_config<ScalarConfig<std::uint8_t>>(*this, b);
      break;
    case ConfigType::kIonosphereConfig:
    case ConfigType::kTroposphereConfig:
      listed = add_config<DelayModelConfig>(*this, b);
      break;
    default:
      break;
  }
  prefix_ = saved;
  if (!listed) blob(name, b, length);
}

}  // namespace navfuse::frontends::fusionengine

#include "frontends/fusionengine/config_types.hpp"

namespace navfuse::frontends::fusionengine {

Point3f point_from_frd(const std::array<double, 3>& frd_m) {
  return {{static_cast<float>(frd_m[0]), static_cast<float>(-frd_m[1]), static_cast<float>(-frd_m[2])}};
}

std::array<double, 3> frd_from_point(const Point3f& p) { return {p.xyz_m[0], -p.xyz_m[1], -p.xyz_m[2]}; }

std::string_view to_string(ConfigType t) {
  switch (t) {
    case ConfigType::kInvalid: return "Invalid";
    case ConfigType::kDeviceLeverArm: return "DeviceLeverArm";
    case ConfigType::kDeviceCoarseOrientation: return "DeviceOrientation";
    case ConfigType::kGnssLeverArm: return "GnssLeverArm";
    case ConfigType::kOutputLeverArm: return "OutputLeverArm";
    case ConfigType::kVehicleDetails: return "VehicleDetails";
    case ConfigType::kWheelConfig: return "WheelConfig";
    case ConfigType::kHardwareTickConfig: return "HardwareTickConfig";
    case ConfigType::kHeadingBias: return "HeadingBias";
    case ConfigType::kGnssAuxLeverArm: return "GnssAuxLeverArm";
    case ConfigType::kEnabledGnssSystems: return "EnabledGnssSystems";
    case ConfigType::kEnabledGnssFrequencyBands: return "EnabledGnssFrequencyBands";
    case ConfigType::kLeapSecond: return "LeapSecondOverride";
    case ConfigType::kGpsWeekRollover: return "GpsWeekRolloverOverride";
    case ConfigType::kIonosphereConfig: return "IonosphereConfig";
    case ConfigType::kTroposphereConfig: return "TroposphereConfig";
    case ConfigType::kInterfaceConfig: return "InterfaceConfig";
    case ConfigType::kUart1BaudRate: return "Uart1BaudRate";
    case ConfigType::kUart2BaudRate: return "Uart2BaudRate";
    case ConfigType::kUart1OutputDiagnostics: return "Uart1DiagEnable";
    case ConfigType::kUart2OutputDiagnostics: return "Uart2DiagEnable";
    case ConfigType::kEnableWatchdogTimer: return "WatchdogEnable";
    case ConfigType::kUserDeviceId: return "UserDeviceId";
    case ConfigType::kProfilingMask: return "ProfilingMask";
    case ConfigType::kLBandParameters: return "LBandParameters";
  }
  return "Reserved";
}

std::size_t config_value_size(std::uint16_t config_type) {
  switch (static_cast<ConfigType>(config_type)) {
    case ConfigType::kDeviceLeverArm:
    case ConfigType::kGnssLeverArm:
    case ConfigType::kOutputLeverArm:
    case ConfigType::kGnssAuxLeverArm:
      return Point3f::kSize;
    case ConfigType::kDeviceCoarseOrientation: return CoarseOrientation::kSize;
    case ConfigType::kVehicleDetails: return VehicleDetails::kSize;
    case ConfigType::kWheelConfig: return WheelConfig::kSize;
    case ConfigType::kHardwareTickConfig: return HardwareTickConfig::kSize;
    case ConfigType::kEnabledGnssSystems:
    case ConfigType::kEnabledGnssFrequencyBands:
    case ConfigType::kLeapSecond:
    case ConfigType::kGpsWeekRollover:
    case ConfigType::kUart1BaudRate:
    case ConfigType::kUart2BaudRate:
      return 4;
    case ConfigType::kIonosphereConfig:
    case ConfigType::kTroposphereConfig:
      return DelayModelConfig::kSize;
    case ConfigType::kUart1OutputDiagnostics:
    case ConfigType::kUart2OutputDiagnostics:
    case ConfigType::kEnableWatchdogTimer:
    case ConfigType::kProfilingMask:
      return 1;
    case ConfigType::kUserDeviceId: return 32;  // char[32] (L996)
    case ConfigType::kLBandParameters: return 28;  // LBandConfig (L1293-1305)
    default: return 0;
  }
}

}  // namespace navfuse::frontends::fusionengine

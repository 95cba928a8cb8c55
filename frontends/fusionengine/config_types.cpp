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

}  // namespace navfuse::frontends::fusionengine

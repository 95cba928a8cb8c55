#include "core/measurements/measurements.hpp"

namespace navfuse {

std::string_view to_string(MeasurementKind kind) {
  switch (kind) {
    case MeasurementKind::kImu: return "imu";
    case MeasurementKind::kGnssPosition: return "gnss_position";
    case MeasurementKind::kGnssVelocity: return "gnss_velocity";
    case MeasurementKind::kGnssHeading: return "gnss_heading";
    case MeasurementKind::kWheelSpeed: return "wheel_speed";
    case MeasurementKind::kVehicleSpeed: return "vehicle_speed";
    case MeasurementKind::kWheelTicks: return "wheel_ticks";
    case MeasurementKind::kExternalPosition: return "external_position";
    case MeasurementKind::kExternalVelocity: return "external_velocity";
    case MeasurementKind::kExternalHeading: return "external_heading";
    case MeasurementKind::kDeviceSolution: return "device_solution";
    case MeasurementKind::kMagnetometer: return "magnetometer";
    case MeasurementKind::kPressure: return "pressure";
    case MeasurementKind::kCount: break;
  }
  return "unknown";
}

std::string_view to_string(NavMode mode) {
  switch (mode) {
    case NavMode::kInvalid: return "invalid";
    case NavMode::kInitializing: return "initializing";
    case NavMode::kVerticalGyro: return "vertical_gyro";
    case NavMode::kAhrs: return "ahrs";
    case NavMode::kNavigation: return "navigation";
    case NavMode::kDeadReckoning: return "dead_reckoning";
    case NavMode::kSmoothed: return "smoothed";
  }
  return "unknown";
}

std::string_view to_string(GnssFixType fix) {
  switch (fix) {
    case GnssFixType::kNone: return "none";
    case GnssFixType::kTimeOnly: return "time_only";
    case GnssFixType::kFix2D: return "2d";
    case GnssFixType::kFix3D: return "3d";
    case GnssFixType::kDgnss: return "dgnss";
    case GnssFixType::kSbas: return "sbas";
    case GnssFixType::kRtkFloat: return "rtk_float";
    case GnssFixType::kRtkFixed: return "rtk_fixed";
    case GnssFixType::kPpp: return "ppp";
    case GnssFixType::kDeadReckoning: return "dead_reckoning";
  }
  return "unknown";
}

std::string_view to_string(TimeSource source) {
  switch (source) {
    case TimeSource::kGps: return "gps";
    case TimeSource::kDeviceMonotonic: return "device";
    case TimeSource::kHostArrival: return "host";
    case TimeSource::kUnknown: return "unknown";
  }
  return "unknown";
}

const MeasurementHeader& header_of(const Measurement& m) {
  return std::visit([](const auto& v) -> const MeasurementHeader& { return v.header; }, m);
}
MeasurementHeader& header_of(Measurement& m) {
  return std::visit([](auto& v) -> MeasurementHeader& { return v.header; }, m);
}

}  // namespace navfuse

// IMU group (group bit 2; ICD Table 2.16, L911-1129; digest §5.3).
#pragma once

#include "frontends/vectornav/binary_message.hpp"
#include "frontends/vectornav/field_io.hpp"

namespace navfuse::frontends::vectornav {

namespace imu_names {
inline constexpr Names3 kUncompMag = {"uncomp_mag_x_gauss", "uncomp_mag_y_gauss", "uncomp_mag_z_gauss"};
inline constexpr Names3 kUncompAccel = {"uncomp_accel_x_mps2", "uncomp_accel_y_mps2", "uncomp_accel_z_mps2"};
inline constexpr Names3 kUncompGyro = {"uncomp_gyro_x_rps", "uncomp_gyro_y_rps", "uncomp_gyro_z_rps"};
inline constexpr Names3 kDeltaTheta = {"delta_theta_x_deg", "delta_theta_y_deg", "delta_theta_z_deg"};
inline constexpr Names3 kDeltaVel = {"delta_vel_x_mps", "delta_vel_y_mps", "delta_vel_z_mps"};
inline constexpr Names3 kMag = {"mag_x_gauss", "mag_y_gauss", "mag_z_gauss"};
inline constexpr Names3 kAccel = {"accel_x_mps2", "accel_y_mps2", "accel_z_mps2"};
inline constexpr Names3 kAngularRate = {"gyro_x_rps", "gyro_y_rps", "gyro_z_rps"};
}  // namespace imu_names

// DeltaTheta type: DeltaTime then the coning-corrected rotation in DEGREES (L1040-1054).
template <class Io>
void visit_delta_theta(Io& io, ImuFields& f) {
  io.field("delta_time_s", f.delta_time_s);
  io.fields(imu_names::kDeltaTheta, f.delta_theta_deg);
}

template <class Io>
void visit_imu_type(unsigned bit, Io& io, ImuFields& f) {
  switch (bit) {
    case imu_type::kImuStatus: io.field("imu_status", f.imu_status); break;
    case imu_type::kUncompMag: io.fields(imu_names::kUncompMag, f.uncomp_mag_gauss); break;
    case imu_type::kUncompAccel: io.fields(imu_names::kUncompAccel, f.uncomp_accel_mps2); break;
    case imu_type::kUncompGyro: io.fields(imu_names::kUncompGyro, f.uncomp_gyro_rps); break;
    case imu_type::kTemperature: io.field("temperature_c", f.temperature_c); break;
    case imu_type::kPressure: io.field("pressure_kpa", f.pressure_kpa); break;
    case imu_type::kDeltaTheta: visit_delta_theta(io, f); break;
    case imu_type::kDeltaVel: io.fields(imu_names::kDeltaVel, f.delta_vel_mps); break;
    case imu_type::kMag: io.fields(imu_names::kMag, f.mag_gauss); break;
    case imu_type::kAccel: io.fields(imu_names::kAccel, f.accel_mps2); break;
    case imu_type::kAngularRate: io.fields(imu_names::kAngularRate, f.angular_rate_rps); break;
    case imu_type::kSensSat: io.field("sens_sat", f.sens_sat); break;
    default: break;
  }
}

// ImuStatus (Table 2.18, L942-951): a 2-bit state per subsystem.
inline constexpr unsigned kImuStatusGyroShift = 0;
inline constexpr unsigned kImuStatusAccelShift = 2;
inline constexpr std::uint16_t kImuStatusFieldMask = 0x3;
inline constexpr std::uint16_t kImuStateNominalUpdated = 0;
inline constexpr std::uint16_t kImuStateSaturated = 2;
inline constexpr std::uint16_t kImuStateFailed = 3;
// SensSat (Table 2.34, L1115-1129): bits 3-5 accel X-Z, bits 6-8 gyro X-Z.
inline constexpr unsigned kSensSatAccelShift = 3;
inline constexpr unsigned kSensSatGyroShift = 6;

}  // namespace navfuse::frontends::vectornav

// The CV7's sensor-to-vehicle transformation commands (0x0C,0x31 Euler, 0x0C,0x32 quaternion,
// 0x0C,0x33 DCM; digest §6.1, L7267-7320) as one rotation matrix C with v_vehicle = C v_sensor.
//   Euler (roll, pitch, yaw) [rad], 3-2-1: C = Rz(yaw) Ry(pitch) Rx(roll) (rot::dcm_from_rpy);
//     the doc's worked examples (L2511-2551) print exactly these matrices for 0x0C,0x33.
//   DCM: row-major, v_veh = M v_sensor (L7312-7313): C = M.
//   Quaternion [w, i, j, k]: p_veh = q^-1 p_sensor q (Hamilton product; the relation is missing
//     from the document's text at L7293, it is MicroStrain's public SDK's), so C = R(q)^T.
// A quaternion more than 1e-3 from unit length, or a matrix more than 1e-3 from orthonormal or
// with a negative determinant, is no rotation: nullopt (the device answers "invalid parameter").
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include <Eigen/Core>

namespace navfuse::frontends::mip {

// `params`: the field's data after the function selector. nullopt also for a descriptor that is
// none of the three or a short field.
std::optional<Eigen::Matrix3d> sensor_to_vehicle_dcm(std::uint8_t desc, std::span<const std::uint8_t> params);

inline constexpr std::uint8_t kSensorToVehicleEuler = 0x31;
inline constexpr std::uint8_t kSensorToVehicleQuaternion = 0x32;
inline constexpr std::uint8_t kSensorToVehicleDcm = 0x33;

}  // namespace navfuse::frontends::mip

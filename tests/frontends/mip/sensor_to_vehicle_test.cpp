// The three forms of the CV7's sensor-to-vehicle transformation give one rotation: the
// document's worked examples (L2511-2551) pair each Euler command with the DCM it prints, and
// the quaternion is worked by hand from p_veh = q^-1 p_sensor q.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "frontends/mip/sensor_to_vehicle.hpp"

namespace navfuse::frontends::mip {
namespace {

// Big-endian f32 parameters, as on the wire.
std::vector<std::uint8_t> floats_be(std::initializer_list<float> values) {
  std::vector<std::uint8_t> out;
  for (float v : values) {
    std::uint32_t u = 0;
    std::memcpy(&u, &v, 4);
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(u >> shift));
  }
  return out;
}

Eigen::Matrix3d row_major(std::initializer_list<double> v) {
  Eigen::Matrix3d m;
  auto it = v.begin();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = *it++;
  return m;
}

TEST(MipSensorToVehicle, DocumentExample2RollMinus90) {
  const Eigen::Matrix3d printed = row_major({1, 0, 0, 0, 0, 1, 0, -1, 0});
  const auto euler = sensor_to_vehicle_dcm(kSensorToVehicleEuler, floats_be({-1.5708f, 0, 0}));
  ASSERT_TRUE(euler);
  EXPECT_TRUE(euler->isApprox(printed, 1e-4)) << *euler;
  const auto dcm = sensor_to_vehicle_dcm(kSensorToVehicleDcm, floats_be({1, 0, 0, 0, 0, 1, 0, -1, 0}));
  ASSERT_TRUE(dcm);
  EXPECT_TRUE(dcm->isApprox(printed)) << *dcm;
  // v_veh = M v_sensor is a rotation about x by -90 deg; p_veh = q^-1 p q makes q the rotation
  // by +90 deg: q = (cos 45, sin 45, 0, 0).
  const float h = static_cast<float>(std::sqrt(0.5));
  const auto quat = sensor_to_vehicle_dcm(kSensorToVehicleQuaternion, floats_be({h, h, 0, 0}));
  ASSERT_TRUE(quat);
  EXPECT_TRUE(quat->isApprox(printed, 1e-6)) << *quat;
}

TEST(MipSensorToVehicle, DocumentExample3YawThenPitch90) {
  const Eigen::Matrix3d printed = row_major({0, -1, 0, 0, 0, 1, -1, 0, 0});
  const auto euler = sensor_to_vehicle_dcm(kSensorToVehicleEuler, floats_be({0, 1.5708f, 1.5708f}));
  ASSERT_TRUE(euler);
  EXPECT_TRUE(euler->isApprox(printed, 1e-4)) << *euler;
  const auto dcm = sensor_to_vehicle_dcm(kSensorToVehicleDcm, floats_be({0, -1, 0, 0, 0, 1, -1, 0, 0}));
  ASSERT_TRUE(dcm);
  EXPECT_TRUE(dcm->isApprox(printed));
}

TEST(MipSensorToVehicle, NoRotationIsRefused) {
  EXPECT_FALSE(sensor_to_vehicle_dcm(kSensorToVehicleQuaternion, floats_be({1, 1, 0, 0})));  // |q| = 1.41
  EXPECT_FALSE(sensor_to_vehicle_dcm(kSensorToVehicleQuaternion, floats_be({0, 0, 0, 0})));
  EXPECT_FALSE(sensor_to_vehicle_dcm(kSensorToVehicleDcm, floats_be({-1, 0, 0, 0, 1, 0, 0, 0, 1})));  // reflection
  EXPECT_FALSE(sensor_to_vehicle_dcm(kSensorToVehicleDcm, floats_be({2, 0, 0, 0, 1, 0, 0, 0, 1})));
  EXPECT_FALSE(sensor_to_vehicle_dcm(kSensorToVehicleDcm, floats_be({1, 0, 0})));  // short
  EXPECT_FALSE(sensor_to_vehicle_dcm(kSensorToVehicleEuler, floats_be({NAN, 0, 0})));
  EXPECT_FALSE(sensor_to_vehicle_dcm(0x30, floats_be({0, 0, 0})));
}

}  // namespace
}  // namespace navfuse::frontends::mip

// Device profiles: names round-trip, and each profile's defaults are sane noise values.
#include <gtest/gtest.h>

#include <cmath>

#include "core/config/config.hpp"

namespace navfuse::config {
namespace {

constexpr DeviceProfile kAll[] = {DeviceProfile::kGeneric, DeviceProfile::kCv7,
                                  DeviceProfile::kVn300, DeviceProfile::kUm220,
                                  DeviceProfile::kFusionEngine};

TEST(DeviceProfiles, NamesRoundTrip) {
  for (DeviceProfile p : kAll) {
    EXPECT_EQ(device_profile_from_string(to_string(p)), p) << to_string(p);
  }
  EXPECT_EQ(device_profile_from_string("VN300"), DeviceProfile::kVn300);  // case-insensitive
  EXPECT_FALSE(device_profile_from_string("vn200").has_value());
  EXPECT_FALSE(device_profile_from_string("").has_value());
}

TEST(DeviceProfiles, DefaultsAreValidNoiseValues) {
  for (DeviceProfile p : kAll) {
    SCOPED_TRACE(std::string(to_string(p)));
    const Config c = defaults_for(p);
    EXPECT_EQ(c.device, p);
    // Every default must itself pass the loader's checks: print it and load it back.
    EXPECT_NO_THROW(load_from_string(to_yaml(c)));
    EXPECT_GT(c.imu.gyro_arw_deg_rthr, 0);
    EXPECT_GT(c.imu.accel_vrw_mps_rthr, 0);
    EXPECT_GT(c.imu.gyro_bias_corr_time_s, 0);
  }
}

TEST(DeviceProfiles, DatasheetFiguresAndOrdering) {
  EXPECT_EQ(defaults_for(DeviceProfile::kCv7).imu.gyro_bias_instability_deg_hr, 1.5);
  EXPECT_EQ(defaults_for(DeviceProfile::kVn300).imu.gyro_bias_instability_deg_hr, 1.0);
  // The generic profile never trusts an unknown IMU more than a named one.
  const Config generic = defaults_for(DeviceProfile::kGeneric);
  for (DeviceProfile p : kAll) {
    const Config c = defaults_for(p);
    EXPECT_LE(c.imu.gyro_arw_deg_rthr, generic.imu.gyro_arw_deg_rthr);
    EXPECT_LE(c.imu.gyro_bias_instability_deg_hr, generic.imu.gyro_bias_instability_deg_hr);
    EXPECT_LE(c.imu.accel_vrw_mps_rthr, generic.imu.accel_vrw_mps_rthr);
    EXPECT_LE(c.imu.accel_bias_instability_mps2, generic.imu.accel_bias_instability_mps2);
  }
}

}  // namespace
}  // namespace navfuse::config

// navfuse configuration: the YAML keys of DESIGN.md (contract) as plain data, with device
// profiles supplying defaults. Loading rejects unknown keys and wrong types with an error that
// names the key (e.g. "imu.gyro_arw_deg_rthr: expected a number, got 'fast'").
//
// Units are in the key names and kept as written in YAML here (deg, deg/hr, ...); the filter
// converts to SI when it builds its noise model.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace navfuse::config {

enum class DeviceProfile { kGeneric, kCv7, kVn300, kUm220, kFusionEngine };
std::string_view to_string(DeviceProfile p);
std::optional<DeviceProfile> device_profile_from_string(std::string_view name);

using Vec3 = std::array<double, 3>;

struct ImuConfig {
  Vec3 mounting_rpy_deg{0, 0, 0};  // sensor -> vehicle, 3-2-1
  double gyro_arw_deg_rthr = 0.08;
  double gyro_bias_instability_deg_hr = 1.5;
  double gyro_bias_corr_time_s = 300;
  double accel_vrw_mps_rthr = 0.02;
  double accel_bias_instability_mps2 = 2.0e-5;
  double accel_bias_corr_time_s = 300;
  double initial_gyro_bias_std_deg_hr = 20;
  double initial_accel_bias_std_mps2 = 0.01;
};

struct GnssConfig {
  Vec3 lever_arm_m{0, 0, 0};            // primary antenna, vehicle frame
  Vec3 secondary_lever_arm_m{0, 0, 0};  // dual-antenna heading, if any
};

struct WheelConfig {
  Vec3 lever_arm_m{0, 0, 0};  // speed measurement point (e.g. rear axle centre)
  double speed_std_mps = 0.05;
};

struct OutputConfig {
  double rate_hz = 100;  // pose output rate (0 = every IMU sample)
};

struct Config {
  DeviceProfile device = DeviceProfile::kGeneric;
  ImuConfig imu;
  GnssConfig gnss;
  WheelConfig wheel;
  OutputConfig output;
};

// Thrown by the loaders; what() is one line naming the file, key and problem.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Defaults for a device profile (before any YAML key is applied).
Config defaults_for(DeviceProfile profile);
// Parses YAML text: `device:` (if present) selects the profile defaults, then every other key
// overrides them. `source_name` is used in error messages.
Config load_from_string(const std::string& yaml_text, const std::string& source_name = "<config>");
Config load_from_file(const std::string& path);

}  // namespace navfuse::config

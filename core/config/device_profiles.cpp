// Device profiles: the IMU noise defaults a config starts from before its own keys apply.
//
// Where a figure comes from:
//  - cv7:  MicroStrain 3DM-CV7 datasheet gyro figures, 1.5 deg/h bias instability and
//          0.08 deg/sqrt(h) angle random walk (also DESIGN.md's example values). The accelerometer
//          figures are typical of its tactical-grade MEMS class (VRW 0.02 m/s/sqrt(h) as in
//          DESIGN.md; bias instability ~10 ug), not quoted from the datasheet.
//  - vn300: VectorNav VN-300 product figures: gyro in-run bias stability ~1 deg/h, gyro noise
//          density 0.0035 deg/s/sqrt(Hz) (x60 -> 0.21 deg/sqrt(h)), accel noise density
//          0.14 mg/sqrt(Hz) (-> 0.14e-3 * 9.80665 * 60 = 0.082 m/s/sqrt(h)), accel in-run bias
//          stability 0.04 mg (-> 3.9e-4 m/s^2).
//  - um220: Unicore UM220-INS carries an automotive consumer-grade MEMS IMU whose noise Unicore
//          does not publish; typical values for that class (gyro ~0.005 deg/s/sqrt(Hz) ->
//          0.3 deg/sqrt(h), ~10 deg/h; accel ~100 ug/sqrt(Hz) -> 0.06 m/s/sqrt(h), ~50 ug).
//  - fusionengine: Point One devices (Atlas, Standard Dev Kit) use automotive-grade IMUs;
//          typical values for that class, slightly better than um220's.
//  - generic: deliberately pessimistic consumer-MEMS values, so an unknown IMU is trusted less,
//          never more, than it deserves.
// Turn-on bias uncertainties are typical values for each class (datasheets rarely give them).
// Correlation times: 300 s for the tactical-grade parts, 100 s for automotive MEMS (typical).
#include <string>

#include "core/config/config.hpp"
#include "core/config/name_table.hpp"

namespace navfuse::config {
namespace {

constexpr EnumName<DeviceProfile> kNames[] = {
    {DeviceProfile::kCv7, "cv7"},
    {DeviceProfile::kVn300, "vn300"},
    {DeviceProfile::kUm220, "um220"},
    {DeviceProfile::kFusionEngine, "fusionengine"},
    {DeviceProfile::kGeneric, "generic"},
};

ImuConfig imu_noise(double arw, double gyro_bi, double gyro_tau, double vrw, double accel_bi,
                    double accel_tau, double gyro_bias0, double accel_bias0) {
  ImuConfig imu;
  imu.gyro_arw_deg_rthr = arw;
  imu.gyro_bias_instability_deg_hr = gyro_bi;
  imu.gyro_bias_corr_time_s = gyro_tau;
  imu.accel_vrw_mps_rthr = vrw;
  imu.accel_bias_instability_mps2 = accel_bi;
  imu.accel_bias_corr_time_s = accel_tau;
  imu.initial_gyro_bias_std_deg_hr = gyro_bias0;
  imu.initial_accel_bias_std_mps2 = accel_bias0;
  return imu;
}

}  // namespace

std::string_view to_string(DeviceProfile p) {
  return name_in<DeviceProfile>(kNames, p, "generic");
}

std::optional<DeviceProfile> device_profile_from_string(std::string_view name) {
  return value_in<DeviceProfile>(kNames, name);
}

Config defaults_for(DeviceProfile profile) {
  Config c;
  c.device = profile;
  //                    ARW    gyro BI tau   VRW    accel BI tau   gyro b0 accel b0
  switch (profile) {
    case DeviceProfile::kCv7:
      c.imu = imu_noise(0.08, 1.5, 300, 0.02, 1.0e-4, 300, 20, 0.01);
      break;
    case DeviceProfile::kVn300:
      c.imu = imu_noise(0.21, 1.0, 300, 0.082, 3.9e-4, 300, 50, 0.02);
      break;
    case DeviceProfile::kUm220:
      c.imu = imu_noise(0.3, 10, 100, 0.06, 5.0e-4, 100, 200, 0.05);
      break;
    case DeviceProfile::kFusionEngine:
      c.imu = imu_noise(0.2, 5, 100, 0.05, 3.0e-4, 100, 150, 0.03);
      break;
    case DeviceProfile::kGeneric:
      c.imu = imu_noise(0.5, 20, 100, 0.1, 1.0e-3, 100, 500, 0.1);
      break;
  }
  return c;
}

}  // namespace navfuse::config

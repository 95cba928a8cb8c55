// --csv: one row per pose, for spreadsheets and plots. Columns (header row first):
//   time_s          measurement time in seconds on the IMU stream's time base: GPS seconds since
//                   1980-01-06 when time_source is "gps" (9 decimals, exact to the ns)
//   time_source     gps | device | host | unknown (core to_string(TimeSource))
//   mode            filter mode (invalid, initializing, vertical_gyro, ahrs, navigation, ...)
//   lat_deg, lon_deg, height_m          WGS-84, ellipsoidal height
//   vn_mps, ve_mps, vd_mps              NED velocity
//   roll_deg, pitch_deg, yaw_deg        vehicle FRD attitude, 3-2-1 Euler
//   pos_std_{n,e,d}_m, vel_std_{n,e,d}_mps, {roll,pitch,yaw}_std_deg   1-sigma
// then, appended (issue 14), the estimated calibration states and their 1-sigma std devs
// (apps/common/calibration_groups.hpp), "nan" where not estimated or before levelling:
//   gyro_bias_{x,y,z}_deg_h, gyro_bias_std_{x,y,z}_deg_h      sensor frame
//   accel_bias_{x,y,z}_mps2, accel_bias_std_{x,y,z}_mps2      sensor frame
//   odometer_scale_error, odometer_scale_error_std           measured = (1 + error) * true
//   mount_{pitch,yaw}_deg, mount_std_{pitch,yaw}_deg         residual mounting
//   gnss_lever_arm_{x,y,z}_m, gnss_lever_arm_std_{x,y,z}_m   vehicle frame, configured + estimated
//   gyro_scale_{x,y,z}_ppm, ..._std_..., accel_scale_{x,y,z}_ppm, ..._std_...
//   gnss_time_offset_ms, gnss_time_offset_std_ms            residual, added to GNSS times
// Numbers use std::to_chars with fixed decimals: independent of the locale, so the same run
// writes the same bytes anywhere.
#pragma once

#include <string>

#include "apps/output/output_file.hpp"
#include "apps/output/pose_writer.hpp"

namespace navfuse::apps {

class CsvPoseWriter final : public PoseWriter {
 public:
  explicit CsvPoseWriter(const std::string& path);
  void write(const OutputEpoch& epoch) override;  // a row at each pose epoch
  void commit() override { file_.commit(); }

 private:
  OutputFile file_;
  std::string row_;  // reused
};

}  // namespace navfuse::apps

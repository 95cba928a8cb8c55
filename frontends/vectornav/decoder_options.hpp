// Options of the VN-300 stream decoder.
#pragma once

#include "core/measurements/measurements.hpp"

namespace navfuse::frontends::vectornav {

struct DecoderOptions {
  // 1-sigma given to the GNSS-compass heading of Reg 98, which states none. Default: the ICD's
  // error model, heading error ~ 0.57 x baseline error [cm] / baseline [m] deg (L4279-4281),
  // with the Reg 93 defaults (1 m baseline known to 2.54 cm): 0.57 * 2.54 / 1 = 1.45 deg.
  double compass_heading_std_deg = 1.45;
  // Frame tag of the IMU outputs. VN "body" outputs are the sensor outputs rotated by Reg 26
  // (L3466-3501), identity by default, so by default they are in the device's case frame and
  // navfuse's configured mounting (imu.mounting_rpy_deg) rotates them into the vehicle frame.
  // Choose kVehicle when Reg 26 already holds the sensor-to-vehicle rotation.
  SensorFrame imu_frame = SensorFrame::kSensor;
};

}  // namespace navfuse::frontends::vectornav

// How large the errors of a device's own INS solution are, by device class: `navfuse sim` writes
// such a solution beside the simulated measurements (the model is apps/simcmd/device_solution_model),
// so that `navfuse bench` can compare navfuse with the device as it would on a real log. Plain
// figures, given by each front-end for the device class it speaks for (FrontendInfo).
#pragma once

namespace navfuse::frontends {

struct DeviceErrorClass {
  // Position: stationary 1-sigma per horizontal / vertical axis and correlation time.
  double horizontal_std_m = 1.0, vertical_std_m = 2.0, position_corr_time_s = 60.0;
  double velocity_std_mps = 0.05, velocity_corr_time_s = 10.0;
  double roll_pitch_std_rad = 0.0, heading_std_rad = 0.0, attitude_corr_time_s = 120.0;
  double outage_accel_std_mps2 = 0.01;  // dead-reckoning drift per GNSS outage
  double rate_hz = 200.0;               // solution output rate
  bool rate_is_imu_rate = false;        // the INS output runs with the IMU (rate_hz then unused)
  double alignment_s = 2.0;             // no solution (initialising) before this
};

}  // namespace navfuse::frontends

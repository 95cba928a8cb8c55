// sim parking_drive (apps/sim/reality_scenarios.hpp: issue 14's description of the held-out car
// drive) written as a VN-300 log with its truth, and the configuration a user of that rig would
// write from the IMU's data sheet: ADIS16465-class noise figures, the mounting and lever arm
// measured, the IMU time offset given or not. For the apps-level scenario tests that hold the
// smoother and the calibration to issue 16's held-out goals.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "apps/simcmd/sim_command.hpp"

namespace navfuse::apps::testing {

struct ParkingDriveLog {
  std::string log_path;
  std::string truth_path;
  std::string config_path;
};

// `gnss_velocity` false: the receiver reports positions only (an RTKLIB .pos without velocity
// columns, the form KF-GINS-style data often comes in). `seed`: another draw of the drive's noise.
inline ParkingDriveLog write_parking_drive(const std::filesystem::path& dir, std::optional<double> imu_time_offset_s,
                                           bool gnss_velocity = true, std::optional<std::uint64_t> seed = std::nullopt) {
  ParkingDriveLog out{(dir / "parking.vnb").string(), (dir / "parking_truth.csv").string(),
                      (dir / "parking.yaml").string()};
  SimOptions sim;
  sim.scenario = "parking_drive";
  sim.format = "vn";
  sim.out_path = out.log_path;
  sim.truth_path = out.truth_path;
  sim.device_rate_hz = 0.0;
  sim.gnss_velocity = gnss_velocity;
  sim.seed = seed;
  run_sim(sim);
  std::ofstream config(out.config_path);
  config << "device: generic\nplatform: land\n"
            "imu:\n  mounting_rpy_deg: [180, 0, -90]\n  gyro_arw_deg_rthr: 0.15\n"
            "  gyro_bias_instability_deg_hr: 2\n  accel_vrw_mps_rthr: 0.03\n"
            "  accel_bias_instability_mps2: 3.5e-5\n  initial_gyro_bias_std_deg_hr: 50\n"
            "  initial_accel_bias_std_mps2: 0.02\n";
  if (imu_time_offset_s) config << "  time_offset_s: " << *imu_time_offset_s << "\n";
  config << "gnss:\n  lever_arm_m: [0.15, -0.30, -0.20]\n";
  return out;
}

}  // namespace navfuse::apps::testing

// What `navfuse smooth --calibration-out F` writes and prints: the configuration with the
// calibrated keys replaced (gnss.lever_arm_m, imu.mounting_rpy_deg, imu.time_offset_s), a
// complete config that `--config F` loads, headed by comments giving every estimate's std dev and
// the estimates that have no config key (odometer scale: the filter estimates it online from
// wheel.initial_scale_std; IMU biases); the calibration table for the summary; its JSON.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "calibration/calibration_result.hpp"
#include "core/config/config.hpp"

namespace navfuse::apps {

// `base` with the estimated keys replaced (values rounded to 0.1 mm, 1e-4 deg, 10 us), each only
// where the log observed it (std dev at most 5 cm, 0.5 deg, 10 ms; the others stay as configured).
config::Config calibrated_config(const config::Config& base, const calib::CalibrationResult& r);
std::string calibration_yaml(const config::Config& base, const calib::CalibrationResult& r);
// The table: parameter, estimate, std dev (one row per axis), then a line on the solve.
std::string calibration_table(const calib::CalibrationResult& r);
nlohmann::ordered_json calibration_json(const calib::CalibrationResult& r);

}  // namespace navfuse::apps

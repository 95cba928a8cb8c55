#include "apps/replay/calibration_output.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

double rounded(double v, double step) { return std::round(v / step) * step; }

// One printable row per scalar: name, unit, value and std in that unit (std 0: held, not estimated).
struct Row {
  std::string name;
  std::string unit;
  double value;
  double std;
};

std::vector<Row> rows(const calib::CalibrationResult& r) {
  std::vector<Row> out;
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    out.push_back({std::string("gnss.lever_arm_m ") + axes[i], "m", r.gnss_lever_arm_m.value[i], r.gnss_lever_arm_m.std[i]});
  }
  const char* angles[] = {"roll", "pitch", "yaw"};
  for (int i = 0; i < 3; ++i) {
    out.push_back({std::string("imu.mounting_rpy_deg ") + angles[i], "deg", r.mounting_rpy_rad.value[i] * rot::kRadToDeg,
                   r.mounting_rpy_rad.std[i] * rot::kRadToDeg});
  }
  out.push_back({"imu.time_offset_s", "ms", r.imu_time_offset_s.value * 1e3, r.imu_time_offset_s.std * 1e3});
  if (r.odometer_scale) {
    out.push_back({"odometer scale (measured/true)", "%", (r.odometer_scale->value - 1.0) * 100.0, r.odometer_scale->std * 100.0});
  }
  for (int i = 0; i < 3; ++i) {
    out.push_back({std::string("gyro bias ") + axes[i], "deg/h", r.gyro_bias_rps.value[i] * rot::kRadToDeg * 3600.0,
                   r.gyro_bias_rps.std[i] * rot::kRadToDeg * 3600.0});
  }
  for (int i = 0; i < 3; ++i) {
    out.push_back({std::string("accel bias ") + axes[i], "mg", r.accel_bias_mps2.value[i] / 9.80665e-3,
                   r.accel_bias_mps2.std[i] / 9.80665e-3});
  }
  for (int i = 0; i < 3; ++i) {
    out.push_back({std::string("gyro scale ") + axes[i], "ppm", r.gyro_scale.value[i] * 1e6, r.gyro_scale.std[i] * 1e6});
  }
  for (int i = 0; i < 3; ++i) {
    out.push_back({std::string("accel scale ") + axes[i], "ppm", r.accel_scale.value[i] * 1e6, r.accel_scale.std[i] * 1e6});
  }
  return out;
}

std::string number(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string solve_line(const calib::CalibrationResult& r) {
  std::ostringstream s;
  s << r.epochs << " epochs, " << r.imu_factors << " IMU factors, " << r.gnss_position_residuals << " GNSS positions, "
    << r.gnss_velocity_residuals << " velocities, " << r.speed_residuals << " wheel speeds, " << r.nhc_residuals
    << " NHC; " << r.iterations << " iterations, " << (r.converged ? "converged" : "NOT converged")
    << ", GNSS position residual RMS " << number(r.position_rms_m, 3) << " m, IMU noise variances x"
    << number(r.imu_noise_scale, 2) << " (IMU residuals " << number(r.imu_variance_factor, 2) << " per dimension), "
    << number(r.wall_s, 1) << " s";
  return s.str();
}

}  // namespace

config::Config calibrated_config(const config::Config& base, const calib::CalibrationResult& r) {
  config::Config c = base;
  for (int i = 0; i < 3; ++i) c.gnss.lever_arm_m[static_cast<std::size_t>(i)] = rounded(r.gnss_lever_arm_m.value[i], 1e-4);
  if (r.mounting_estimated && !r.mounting_is_residual) {
    for (int i = 0; i < 3; ++i) {
      c.imu.mounting_rpy_deg[static_cast<std::size_t>(i)] = rounded(r.mounting_rpy_rad.value[i] * rot::kRadToDeg, 1e-4);
    }
  }
  c.imu.time_offset_s = rounded(r.imu_time_offset_s.value, 1e-5);
  return c;
}

std::string calibration_yaml(const config::Config& base, const calib::CalibrationResult& r) {
  std::ostringstream s;
  s << "# navfuse smooth --calibration-out: the configuration with the calibrated keys replaced\n"
       "# (gnss.lever_arm_m, imu.mounting_rpy_deg pitch and yaw, imu.time_offset_s). Estimates and 1-sigma\n"
       "# std devs from the solver's covariance (0: held at the configured value, not estimated):\n";
  for (const Row& row : rows(r)) {
    s << "#   " << row.name << ": " << number(row.value, 4) << " +- " << number(row.std, 4) << " " << row.unit << "\n";
  }
  if (r.odometer_scale) {
    s << "# The odometer scale has no config key (the filter estimates it online, wheel.initial_scale_std).\n";
  }
  if (r.mounting_is_residual) {
    s << "# The IMU reports in the vehicle frame (the device applies its own mounting): the mounting above is\n"
         "# the residual to set in the device, not imu.mounting_rpy_deg (left as configured).\n";
  }
  s << "# IMU biases and scale factors are this log's, sensor frame, for reference (no config key).\n";
  s << "# Solve: " << solve_line(r) << "\n";
  s << config::to_yaml(calibrated_config(base, r));
  return s.str();
}

std::string calibration_table(const calib::CalibrationResult& r) {
  std::ostringstream s;
  s << "calibration:\n";
  char line[160];
  std::snprintf(line, sizeof line, "  %-32s %12s %12s  %s\n", "parameter", "estimate", "std dev", "unit");
  s << line;
  for (const Row& row : rows(r)) {
    std::snprintf(line, sizeof line, "  %-32s %12.4f %12s  %s\n", row.name.c_str(), row.value,
                  row.std > 0.0 ? number(row.std, 4).c_str() : "held", row.unit.c_str());
    s << line;
  }
  s << "  " << solve_line(r) << "\n";
  if (!r.message.empty() && !r.converged) s << "  solver: " << r.message << "\n";
  return s.str();
}

nlohmann::ordered_json calibration_json(const calib::CalibrationResult& r) {
  nlohmann::ordered_json j;
  for (const Row& row : rows(r)) j["parameters"][row.name] = {{"estimate", row.value}, {"std", row.std}, {"unit", row.unit}};
  j["epochs"] = r.epochs;
  j["imu_factors"] = r.imu_factors;
  j["gnss_position_residuals"] = r.gnss_position_residuals;
  j["gnss_velocity_residuals"] = r.gnss_velocity_residuals;
  j["speed_residuals"] = r.speed_residuals;
  j["nhc_residuals"] = r.nhc_residuals;
  j["iterations"] = r.iterations;
  j["converged"] = r.converged;
  j["covariance_ok"] = r.covariance_ok;
  j["position_rms_m"] = r.position_rms_m;
  j["imu_noise_scale"] = r.imu_noise_scale;
  j["imu_variance_factor"] = r.imu_variance_factor;
  j["wall_s"] = r.wall_s;
  j["message"] = r.message;
  return j;
}

}  // namespace navfuse::apps

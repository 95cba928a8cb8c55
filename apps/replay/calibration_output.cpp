#include "apps/replay/calibration_output.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "calibration/mounting_rotation.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/filter_options.hpp"

namespace navfuse::apps {
namespace {

constexpr double kMps2PerMg = 9.80665e-3;  // standard gravity / 1000
constexpr double kDegHPerRps = rot::kRadToDeg * 3600.0;
// A random walk's density per sqrt(s) to per sqrt(h), as the config's imu.*_rthr keys take it.
constexpr double kPerRthrPerRts = 60.0;
constexpr double kDegRthrPerRadRts = rot::kRadToDeg * kPerRthrPerRts;

// A bias segment's start from the first segment's (the log's first epoch).
double segment_start_s(const calib::CalibrationResult& r, const calib::CalibrationResult::BiasSegment& b) {
  return static_cast<double>(b.start_ns - r.bias_segments.front().start_ns) * 1e-9;
}

// To a whole number of `decimals` places. Divided by the power of ten (exact in binary) rather than
// multiplied by its inverse (not exact): the result is then the double nearest the decimal, which
// the config writer prints as it reads (-0.12932, not -0.12932000000000002).
double rounded(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

// An estimate is written into the configuration only when the log observed it: its std dev at
// most these. Beyond them the fit held it near its prior and moved it by whatever the model lacks
// (on parking_drive with positions only the vertical lever arm went from -0.20 to +2.7 m, std
// 1.0 m; with velocities to +0.07, std 0.18: written back, the next round's heights were 0.25 m
// off); a value that poorly known is no better than the configured one, which stays.
constexpr double kWrittenLeverArmStd_m = 0.05;
constexpr double kWrittenMountingStd_rad = 0.5 * rot::kDegToRad;
constexpr double kWrittenTimeOffsetStd_s = 0.010;
// The non-slip point moves the constraint by yaw rate x error: 10 cm is 5 cm/s in a 0.5 rad/s
// car-park turn, half the constraint's own std.
constexpr double kWrittenNhcPointStd_m = 0.10;

bool observed(double std, double bound) { return std > 0.0 && std <= bound; }

// What calibrated_config() writes of each estimate.
struct Written {
  std::array<bool, 3> lever{};
  std::array<bool, 2> mounting{};  // vehicle pitch, yaw residuals
  bool time_offset = false;
  std::array<bool, 3> nhc_point{};
};

Written written(const calib::CalibrationResult& r) {
  Written w;
  if (!r.covariance_ok) return w;
  for (int i = 0; i < 3; ++i) w.lever[static_cast<std::size_t>(i)] = observed(r.gnss_lever_arm_m.std[i], kWrittenLeverArmStd_m);
  for (int i = 0; i < 2; ++i) {
    w.mounting[static_cast<std::size_t>(i)] = r.mounting_estimated && !r.mounting_is_residual &&
                                              observed(r.mounting_residual_rad.std[i], kWrittenMountingStd_rad);
  }
  w.time_offset = observed(r.imu_time_offset_s.std, kWrittenTimeOffsetStd_s);
  for (int i = 0; i < 3; ++i) {
    w.nhc_point[static_cast<std::size_t>(i)] =
        r.nhc_lever_arm_estimated && observed(r.nhc_lever_arm_m.std[i], kWrittenNhcPointStd_m);
  }
  return w;
}

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
  // What the fit estimates (calibration/mounting_rotation.hpp): the vehicle frame turned about its
  // own y and z axes from the configured mounting; the Euler angles above follow from it.
  const char* residuals[] = {"mounting vehicle pitch residual", "mounting vehicle yaw residual"};
  for (int i = 0; i < 2; ++i) {
    out.push_back({residuals[i], "deg", r.mounting_residual_rad.value[i] * rot::kRadToDeg,
                   r.mounting_residual_rad.std[i] * rot::kRadToDeg});
  }
  out.push_back({"imu.time_offset_s", "ms", r.imu_time_offset_s.value * 1e3, r.imu_time_offset_s.std * 1e3});
  if (r.nhc_lever_arm_estimated) {
    for (int i = 0; i < 3; ++i) {
      out.push_back({std::string("nhc.lever_arm_m ") + axes[i], "m", r.nhc_lever_arm_m.value[i], r.nhc_lever_arm_m.std[i]});
    }
  }
  if (r.odometer_scale) {
    out.push_back({"odometer scale (measured/true)", "%", (r.odometer_scale->value - 1.0) * 100.0, r.odometer_scale->std * 100.0});
  }
  for (int i = 0; i < 3; ++i) {
    out.push_back({std::string("gyro bias ") + axes[i], "deg/h", r.gyro_bias_rps.value[i] * kDegHPerRps,
                   r.gyro_bias_rps.std[i] * kDegHPerRps});
  }
  for (int i = 0; i < 3; ++i) {
    out.push_back({std::string("accel bias ") + axes[i], "mg", r.accel_bias_mps2.value[i] / kMps2PerMg,
                   r.accel_bias_mps2.std[i] / kMps2PerMg});
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
    << r.gnss_velocity_residuals << " velocities, " << r.gnss_heading_residuals << " headings, " << r.external_residuals
    << " external aiding, " << r.speed_residuals << " wheel speeds, " << r.nhc_residuals << " NHC, " << r.bias_segments.size() << " bias segment(s); " << r.iterations << " iterations, " << (r.converged ? "converged" : "NOT converged")
    << ", GNSS position residual RMS " << number(r.position_rms_m, 3) << " m, IMU noise variances x"
    << number(r.imu_noise_scale, 2) << " (IMU residuals " << number(r.imu_variance_factor, 2) << " per dimension), ";
  if (r.measured_gyro_noise_rad_rts > 0.0) {
    s << "IMU white noise in its samples " << number(r.measured_gyro_noise_rad_rts * kDegRthrPerRadRts, 3)
      << " deg/sqrt(h), " << number(r.measured_accel_noise_mps_rts * kPerRthrPerRts, 3) << " m/s/sqrt(h) (median), ";
  }
  s << number(r.wall_s, 1) << " s";
  return s.str();
}

}  // namespace

config::Config calibrated_config(const config::Config& base, const calib::CalibrationResult& r) {
  config::Config c = base;
  const Written w = written(r);
  for (std::size_t i = 0; i < 3; ++i) {
    if (w.lever[i]) c.gnss.lever_arm_m[i] = rounded(r.gnss_lever_arm_m.value[static_cast<int>(i)], 4);
  }
  if (w.mounting[0] || w.mounting[1]) {
    // The configured mounting turned by the observed residuals only (mounting_rotation.hpp).
    const double residual[2] = {w.mounting[0] ? r.mounting_residual_rad.value.x() : 0.0,
                                w.mounting[1] ? r.mounting_residual_rad.value.y() : 0.0};
    const Eigen::Vector3d rpy0(base.imu.mounting_rpy_deg[0], base.imu.mounting_rpy_deg[1], base.imu.mounting_rpy_deg[2]);
    const Eigen::Vector3d rpy = rot::rpy_from_dcm(calib::mounting_dcm(residual, rot::dcm_from_rpy(rpy0 * rot::kDegToRad)));
    for (int i = 0; i < 3; ++i) c.imu.mounting_rpy_deg[static_cast<std::size_t>(i)] = rounded(rpy[i] * rot::kRadToDeg, 4);
  }
  if (w.time_offset) c.imu.time_offset_s = rounded(r.imu_time_offset_s.value, 5);
  if (w.nhc_point[0] || w.nhc_point[1] || w.nhc_point[2]) {
    // The point where observed, the guess elsewhere, each with how well it is now known, so the
    // next run neither takes the guess for a measurement nor forgets the calibration's std.
    const filter::FilterOptions configured = filter::options_from_config(base);
    const Eigen::Vector3d guess = configured.nhc_point_m();
    const Eigen::Vector3d guess_std = configured.nhc_lever_arm_std_m;
    config::Vec3 point{}, point_std{};
    for (std::size_t i = 0; i < 3; ++i) {
      const int a = static_cast<int>(i);
      point[i] = w.nhc_point[i] ? rounded(r.nhc_lever_arm_m.value[a], 3) : guess[a];
      point_std[i] = w.nhc_point[i] ? std::max(0.001, rounded(r.nhc_lever_arm_m.std[a], 3)) : guess_std[a];
    }
    c.nhc.lever_arm_m = point;
    c.nhc.lever_arm_std_m = point_std;
  }
  return c;
}

std::string calibration_yaml(const config::Config& base, const calib::CalibrationResult& r) {
  std::ostringstream s;
  s << "# navfuse smooth --calibration-out: the configuration with the calibrated keys replaced\n"
       "# (gnss.lever_arm_m, imu.mounting_rpy_deg, imu.time_offset_s, and nhc.lever_arm_m where the\n"
       "# config only guessed it). Estimates and 1-sigma std devs from the solver's covariance (0: held\n"
       "# at the configured value, not estimated):\n";
  for (const Row& row : rows(r)) {
    s << "#   " << row.name << ": " << number(row.value, 4) << " +- " << number(row.std, 4) << " " << row.unit << "\n";
  }
  if (r.odometer_scale) {
    s << "# The odometer scale has no config key (the filter estimates it online, wheel.initial_scale_std).\n";
  }
  const Written w = written(r);
  std::string kept;
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (!w.lever[static_cast<std::size_t>(i)]) kept += std::string(" gnss.lever_arm_m ") + axes[i] + ";";
  }
  const char* turns[] = {"pitch", "yaw"};
  for (int i = 0; i < 2; ++i) {
    if (r.mounting_estimated && !r.mounting_is_residual && !w.mounting[static_cast<std::size_t>(i)]) {
      kept += std::string(" mounting vehicle ") + turns[i] + " residual;";
    }
  }
  if (!w.time_offset) kept += " imu.time_offset_s;";
  for (int i = 0; i < 3; ++i) {
    if (r.nhc_lever_arm_estimated && !w.nhc_point[static_cast<std::size_t>(i)]) {
      kept += std::string(" nhc.lever_arm_m ") + axes[i] + ";";
    }
  }
  if (!kept.empty()) {
    kept.pop_back();
    s << "# Not observed well enough to write (std dev above 5 cm, 0.5 deg, 10 ms, 10 cm for the non-slip\n"
         "# point), kept as configured:" << kept << "\n";
  }
  if (r.mounting_is_residual) {
    s << "# The IMU reports in the vehicle frame (the device applies its own mounting): the mounting above is\n"
         "# the residual to set in the device, not imu.mounting_rpy_deg (left as configured).\n";
  }
  s << "# IMU biases and scale factors are this log's, sensor frame, for reference (no config key); the\n"
       "# biases are the mean over " << r.bias_segments.size() << " segment(s) of the log (bias_segments.hpp); each:\n";
  for (const calib::CalibrationResult::BiasSegment& b : r.bias_segments) {
    s << "#   from " << number(segment_start_s(r, b), 1) << " s: gyro";
    for (int i = 0; i < 3; ++i) s << " " << number(b.gyro_bias_rps.value[i] * kDegHPerRps, 2);
    s << " deg/h, accel";
    for (int i = 0; i < 3; ++i) s << " " << number(b.accel_bias_mps2.value[i] / kMps2PerMg, 3);
    s << " mg\n";
  }
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
  for (const calib::CalibrationResult::BiasSegment& b : r.bias_segments) {
    nlohmann::ordered_json seg;
    seg["start_s"] = segment_start_s(r, b);
    for (int i = 0; i < 3; ++i) {
      seg["gyro_bias_deg_h"].push_back(b.gyro_bias_rps.value[i] * kDegHPerRps);
      seg["gyro_bias_std_deg_h"].push_back(b.gyro_bias_rps.std[i] * kDegHPerRps);
      seg["accel_bias_mg"].push_back(b.accel_bias_mps2.value[i] / kMps2PerMg);
      seg["accel_bias_std_mg"].push_back(b.accel_bias_mps2.std[i] / kMps2PerMg);
    }
    j["bias_segments"].push_back(seg);
  }
  j["epochs"] = r.epochs;
  j["imu_factors"] = r.imu_factors;
  j["gnss_position_residuals"] = r.gnss_position_residuals;
  j["gnss_velocity_residuals"] = r.gnss_velocity_residuals;
  j["gnss_heading_residuals"] = r.gnss_heading_residuals;
  j["external_residuals"] = r.external_residuals;
  j["speed_residuals"] = r.speed_residuals;
  j["nhc_residuals"] = r.nhc_residuals;
  j["iterations"] = r.iterations;
  j["converged"] = r.converged;
  j["covariance_ok"] = r.covariance_ok;
  j["position_rms_m"] = r.position_rms_m;
  j["imu_noise_scale"] = r.imu_noise_scale;
  j["imu_variance_factor"] = r.imu_variance_factor;
  j["measured_gyro_arw_deg_rthr"] = r.measured_gyro_noise_rad_rts * kDegRthrPerRadRts;
  j["measured_accel_vrw_mps_rthr"] = r.measured_accel_noise_mps_rts * kPerRthrPerRts;
  j["wall_s"] = r.wall_s;
  j["message"] = r.message;
  return j;
}

}  // namespace navfuse::apps

// Runs a simulator scenario through the Engine and compares every IMU-epoch solution with the
// simulator's truth: horizontal / attitude errors, the first time full navigation was reached and
// the NEES of position, velocity and attitude (error^T P^-1 error with the filter's own P).
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include <Eigen/Cholesky>

#include "apps/sim/scenarios.hpp"
#include "apps/sim/simulator.hpp"
#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"

namespace navfuse::filter::test {

// Filter options matching the simulator's IMU error spec (the config keys a user would set for
// this IMU from its datasheet) and the scenario's lever arms.
inline FilterOptions options_for(const sim::Scenario& s) {
  FilterOptions o;
  const auto& e = s.imu.errors;
  o.imu.gyro_arw_rad_rts = e.gyro_arw_deg_rthr * rot::kDegToRad / 60.0;
  o.imu.gyro_bias_std_rps = e.gyro_bias_instability_deg_hr * rot::kDegToRad / 3600.0;
  o.imu.gyro_bias_corr_time_s = e.gyro_bias_corr_time_s;
  o.imu.initial_gyro_bias_std_rps =
      std::hypot(e.gyro_turn_on_bias_std_deg_hr, e.gyro_bias_instability_deg_hr) * rot::kDegToRad / 3600.0;
  o.imu.accel_vrw_mps_rts = e.accel_vrw_mps_rthr / 60.0;
  o.imu.accel_bias_std_mps2 = e.accel_bias_instability_mps2;
  o.imu.accel_bias_corr_time_s = e.accel_bias_corr_time_s;
  o.imu.initial_accel_bias_std_mps2 = std::hypot(e.accel_turn_on_bias_std_mps2, e.accel_bias_instability_mps2);
  o.imu.initial_gyro_scale_std = std::max(e.gyro_scale_factor_std_ppm, 1.0) * 1e-6;
  o.imu.initial_accel_scale_std = std::max(e.accel_scale_factor_std_ppm, 1.0) * 1e-6;
  o.mounting_rpy_rad = s.imu.mounting_rpy_deg * rot::kDegToRad;
  o.gnss_lever_arm_m = s.gnss.lever_arm_m;
  o.gnss_secondary_lever_arm_m = s.gnss.secondary_lever_arm_m;
  o.wheel_lever_arm_m = s.wheel.lever_arm_m;
  o.wheel_speed_std_mps = s.wheel.noise_std_mps;
  // Where the simulated vehicle does not slip sideways: its reference point (the IMU) unless the
  // scenario moves it (a real car: the rear-axle centre).
  o.nhc_lever_arm_m = s.trajectory.nonslip_point_m;
  return o;
}

struct Epoch {
  double t_s = 0.0;  // since scenario start
  const sim::TruthSample* truth = nullptr;
  const Engine* engine = nullptr;
  Eigen::Vector3d pos_err_ned_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d vel_err_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d att_err_rad = Eigen::Vector3d::Zero();  // phi, NED
  Eigen::Vector3d rpy_err_rad = Eigen::Vector3d::Zero();
  double horizontal_m() const { return pos_err_ned_m.head<2>().norm(); }
};

inline double nees(const Eigen::Vector3d& e, const Eigen::Matrix3d& p) {
  return e.dot(p.ldlt().solve(e));
}

// Streams `scenario` into a fresh Engine; `on_epoch` sees every IMU epoch; `filter_measurement`
// may drop or edit measurements before the engine sees them (return false to drop).
struct RunSummary {
  double first_navigation_s = -1.0;
  double first_speed_2mps_s = -1.0;
  std::uint64_t imu_epochs = 0;
  FilterStats stats;
};

inline RunSummary run_scenario(const sim::Scenario& scenario, const FilterOptions& options,
                               const std::function<void(const Epoch&)>& on_epoch,
                               const std::function<bool(Measurement&)>& filter_measurement = {}) {
  sim::Simulator sim(scenario);
  Engine engine(options);
  RunSummary summary;
  Measurement m;
  while (sim.next(m)) {
    if (filter_measurement && !filter_measurement(m)) continue;
    engine.process(m);
    if (kind_of(m) != MeasurementKind::kImu) continue;
    const sim::TruthSample& truth = sim.truth();
    const NavSolution& sol = engine.solution();
    Epoch ep;
    ep.t_s = static_cast<double>(truth.time_ns - sim.start_time_ns()) * 1e-9;
    ep.truth = &truth;
    ep.engine = &engine;
    ep.pos_err_ned_m = geo::ned_offset_m(truth.llh, {sol.lat_rad, sol.lon_rad, sol.height_m});
    ep.vel_err_ned_mps = sol.vel_ned_mps - truth.vel_ned_mps;
    // C_true = (I + [phi x]) C_est  =>  phi = rotvec(q_true q_est^-1) (estimate minus truth: -phi).
    ep.att_err_rad = -rot::rotvec_from_quat(truth.q_nb * sol.q_nb.conjugate());
    ep.rpy_err_rad = sol.rpy_rad - truth.rpy_rad;
    ep.rpy_err_rad.z() = rot::wrap_pi(ep.rpy_err_rad.z());
    if (summary.first_speed_2mps_s < 0.0 && truth.vel_ned_mps.head<2>().norm() > 2.0) {
      summary.first_speed_2mps_s = ep.t_s;
    }
    if (summary.first_navigation_s < 0.0 && sol.mode == NavMode::kNavigation) {
      summary.first_navigation_s = ep.t_s;
    }
    ++summary.imu_epochs;
    if (on_epoch) on_epoch(ep);
  }
  summary.stats = engine.stats();
  return summary;
}

// Root mean square accumulator.
struct Rms {
  double sum_sq = 0.0;
  std::size_t n = 0;
  void add(double v) { sum_sq += v * v; ++n; }
  double value() const { return n == 0 ? 0.0 : std::sqrt(sum_sq / static_cast<double>(n)); }
};

}  // namespace navfuse::filter::test

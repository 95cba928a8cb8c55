// A CalibrationLog straight from the simulator (apps/sim): the measurements as the filter would
// take them and the truth as the starting trajectory, optionally disturbed; and the truth of the
// installation to compare the calibration with.
#pragma once

#include <cmath>

#include "apps/sim/scenarios.hpp"
#include "apps/sim/simulator.hpp"
#include "calibration/calibration_log.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::calib::testing {

struct SimLog {
  CalibrationLog log;
  sim::Scenario scenario;
};

// What the calibration starts from (as a configuration would give it).
struct StartingSetup {
  Eigen::Vector3d lever_arm_m;
  Eigen::Vector3d mounting_rpy_deg;
  double imu_time_offset_s;
};

// `scenario`'s measurements. The trajectory to start from is the truth as a smoother on the
// configured clock would give it: the state at IMU stamp s is the truth at GPS time s + the
// configured offset (not the true one), its attitude the vehicle's.
inline SimLog sim_log(const sim::Scenario& scenario, const StartingSetup& start) {
  SimLog out;
  out.scenario = scenario;
  const sim::SimulationOutput sim = sim::simulate(scenario);
  CalibrationLog& log = out.log;
  CalibrationSetup& s = log.setup;
  s.gnss_lever_arm_m = start.lever_arm_m;
  s.mounting_rpy_rad = start.mounting_rpy_deg * rot::kDegToRad;
  s.imu_time_offset_s = start.imu_time_offset_s;
  s.wheel_lever_arm_m = scenario.wheel.lever_arm_m;
  if (scenario.gnss.heading) s.heading_baseline_v_m = scenario.gnss.secondary_lever_arm_m - scenario.gnss.lever_arm_m;
  s.nhc_lever_arm_m = scenario.trajectory.nonslip_point_m;  // where the simulated vehicle does not slip
  s.land_vehicle = true;
  s.gyro_arw_rad_rts = 0.1 * rot::kDegToRad / 60.0;
  s.accel_vrw_mps_rts = 0.03 / 60.0;
  // Bias drift densities of the industrial grade (2 deg/h, 0.02 mg over 300 s, Gauss-Markov).
  s.gyro_bias_std_rps = 2.0 * rot::kDegToRad / 3600.0 * std::sqrt(2.0 / 300.0);
  s.accel_bias_std_mps2 = 0.02 * 9.80665e-3 * std::sqrt(2.0 / 300.0);
  const auto offset_ns = time::nanoseconds(start.imu_time_offset_s);
  for (const Measurement& m : sim.measurements) {
    if (const auto* imu = std::get_if<ImuSample>(&m)) log.imu.push_back(*imu);
    if (const auto* p = std::get_if<GnssPosition>(&m)) log.positions.push_back(*p);
    if (const auto* v = std::get_if<GnssVelocity>(&m)) log.velocities.push_back(*v);
    if (const auto* h = std::get_if<GnssHeading>(&m)) log.headings.push_back(*h);
    if (const auto* w = std::get_if<VehicleSpeed>(&m)) {
      log.speeds.push_back({.time_ns = w->header.time_ns, .speed_mps = w->speed_mps, .std_mps = w->speed_std_mps});
    }
  }
  for (const sim::TruthSample& t : sim.truth) {
    if (t.time_ns < scenario.start_time_ns + time::nanoseconds(30.0)) continue;  // after the static start
    log.trajectory.push_back({.time_ns = t.time_ns - offset_ns,
                              .lat_rad = t.llh.lat_rad,
                              .lon_rad = t.llh.lon_rad,
                              .height_m = t.llh.height_m,
                              .vel_ned_mps = t.vel_ned_mps,
                              .q_nv = t.q_nb,
                              .gyro_bias_v_rps = t.gyro_bias_vehicle_rps,
                              .accel_bias_v_mps2 = t.accel_bias_vehicle_mps2});
  }
  return out;
}

}  // namespace navfuse::calib::testing

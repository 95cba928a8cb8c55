// A plausible "device INS" solution for simulated logs (`navfuse sim`), so that `navfuse bench`
// can compare navfuse with the device's own output as it would with a real log.
//
// The device solution is the truth plus errors of the size a device of the class shows
// (not a second filter run): per NED axis and per attitude angle, a first-order Gauss-Markov
// error (stationary std sigma, correlation time tau; discretised exactly,
// e_k = e^(-dt/tau) e_(k-1) + sqrt(1 - e^(-2 dt/tau)) sigma w_k, as for the simulator's IMU bias)
// models the slowly wandering, bias-like error of a GNSS-aided INS. While GNSS is out
// (truth.gnss_available = 0) the device dead-reckons: a constant acceleration error drawn per
// outage (the residual accelerometer bias / tilt of the class) integrates into a velocity error
// and a quadratically growing position error (Groves §14.2.1: horizontal drift ~ 1/2 b t^2),
// which decays back (tau 5 s) once GNSS returns. The reported 1-sigma values are the model's.
//
// The class figures below are typical of the device classes, not datasheet guarantees:
//   vn (VN-300, dual-antenna, industrial MEMS)     1.0 m / 2.0 m, 0.05 m/s, 0.05 deg r/p, 0.2 deg hdg
//   mip (3DM-CV7-INS, single antenna)              1.0 m / 2.0 m, 0.05 m/s, 0.1 deg r/p, 0.5 deg hdg
//   unicore (UM220-INS, automotive MEMS)           1.5 m / 3.0 m, 0.1 m/s, 0.3 deg r/p, 1.0 deg hdg
//   fe (Point One, GNSS/INS with corrections)      0.5 m / 1.0 m, 0.03 m/s, 0.05 deg r/p, 0.2 deg hdg
#pragma once

#include <cstdint>
#include <string_view>

#include <Eigen/Core>

#include "apps/sim/random.hpp"
#include "apps/sim/trajectory.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

struct DeviceErrorClass {
  double horizontal_std_m = 1.0, vertical_std_m = 2.0, position_corr_time_s = 60.0;
  double velocity_std_mps = 0.05, velocity_corr_time_s = 10.0;
  double roll_pitch_std_rad = 0.0, heading_std_rad = 0.0, attitude_corr_time_s = 120.0;
  double outage_accel_std_mps2 = 0.01;  // dead-reckoning drift per outage
  double rate_hz = 200.0;               // solution output rate
  double alignment_s = 2.0;             // no solution (initialising) before this
};

// Figures for a format ("vn", "mip", "unicore", "fe"); `imu_rate_hz` is the rate of vn/mip,
// whose INS output runs with the IMU.
DeviceErrorClass device_error_class(std::string_view format, double imu_rate_hz);

class DeviceSolutionModel {
 public:
  DeviceSolutionModel(const DeviceErrorClass& errors, std::int64_t start_time_ns, std::uint64_t seed);

  // Advances the error processes to `truth.time_ns` (call at every IMU sample); returns true and
  // fills `out` when a solution is due on the output-rate grid.
  bool step(const sim::TruthSample& truth, NavSolution& out);

 private:
  void propagate(double dt_s, bool gnss);

  DeviceErrorClass c_;
  std::int64_t start_ns_;
  std::int64_t period_ns_;
  std::int64_t last_ns_;
  sim::Rng rng_;
  Eigen::Vector3d pos_err_m_ = Eigen::Vector3d::Zero();  // NED
  Eigen::Vector3d vel_err_mps_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d att_err_rad_ = Eigen::Vector3d::Zero();  // roll, pitch, yaw
  Eigen::Vector3d outage_accel_mps2_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d drift_vel_mps_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d drift_pos_m_ = Eigen::Vector3d::Zero();
  double outage_s_ = 0.0;
  bool in_outage_ = false;
};

}  // namespace navfuse::apps

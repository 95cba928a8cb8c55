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
// The figures of each device class (frontends::DeviceErrorClass) come with its front-end
// (FrontendInfo::device_errors, in frontends/<protocol>/frontend.cpp).
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "apps/sim/random.hpp"
#include "apps/sim/trajectory.hpp"
#include "core/measurements/measurements.hpp"
#include "frontends/common/frontend_info.hpp"

namespace navfuse::apps {

using frontends::DeviceErrorClass;

// The figures of a front-end's device class, with the solution rate resolved: `imu_rate_hz` for a
// device whose INS output runs with the IMU.
DeviceErrorClass device_error_class(const frontends::FrontendInfo& frontend, double imu_rate_hz);

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

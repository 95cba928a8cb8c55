// Strapdown inertial mechanisation in the local NED frame (Shin 2005 thesis §2.2, the velocity /
// position / attitude update of Savage 1998 "Strapdown Inertial Navigation Integration Algorithm
// Design", parts 1 and 2), driven by angle and velocity increments in the vehicle frame.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "core/geodesy/geodesy.hpp"
#include "core/measurements/measurements.hpp"
#include "filter/nav_state.hpp"

namespace navfuse::filter {

// One IMU interval, already rotated into the vehicle frame: raw (uncompensated) increments.
struct ImuIncrement {
  std::int64_t time_ns = 0;  // end of the interval
  double dt_s = 0.0;
  Eigen::Vector3d dtheta_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d dvel_mps = Eigen::Vector3d::Zero();
  // kCompensated: the device did the coning, rotation and sculling terms; strapdown_step adds them
  // only to raw integrals.
  ImuIncrements contents = ImuIncrements::kRawIntegrals;
};

// Earth quantities that change only with position: evaluated once per covariance step and reused
// by every IMU sample in it (gravity varies ~3e-6 m/s^2 per metre of height, radii far less).
struct LocalEarth {
  double lat_rad = 0.0;
  double height_m = 0.0;
  geo::Radii radii;
  Eigen::Vector3d gravity_ned_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d earth_rate_ned_rps = Eigen::Vector3d::Zero();

  static LocalEarth at(double lat_rad, double height_m);
  // Transport rate omega_en for a velocity at this place (Groves eq. 5.44), with cached radii.
  Eigen::Vector3d transport_rate(const Eigen::Vector3d& vel_ned_mps) const;
};

// Remembers the previous interval for the two-sample coning and sculling terms.
struct StrapdownMemory {
  Eigen::Vector3d prev_dtheta_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d prev_dvel_mps = Eigen::Vector3d::Zero();
  bool has_prev = false;
};

// Removes the estimated biases and scale factors from raw increments.
ImuIncrement compensate(const ImuIncrement& raw, const NavState& x);

// Advances position, velocity and attitude over one compensated interval.
void strapdown_step(NavState& x, StrapdownMemory& memory, const ImuIncrement& compensated,
                    const LocalEarth& earth);

}  // namespace navfuse::filter

// What every measurement model reads: the nominal state plus quantities derived from it once per
// update (attitude matrix, compensated angular rate, local earth).
#pragma once

#include <Eigen/Core>

#include "filter/ekf.hpp"
#include "filter/nav_state.hpp"
#include "filter/strapdown.hpp"

namespace navfuse::filter {

struct StateView {
  const NavState& x;
  const LocalEarth& earth;
  Eigen::Matrix3d c_nb;
  Eigen::Vector3d rate_b_rps;  // compensated angular rate w_ib, vehicle frame
  double shift_s = 0.0;        // measurement time minus state time (|shift| < one IMU interval)

  StateView(const NavState& state, const LocalEarth& local, const Eigen::Vector3d& rate, double shift)
      : x(state), earth(local), c_nb(state.q_nb.toRotationMatrix()), rate_b_rps(rate), shift_s(shift) {}
};

// h(x_hat) - z for positions, in NED metres at the estimate (locally linear: the residuals are
// metres to kilometres, where the curvature error is far below a millimetre).
Eigen::Vector3d position_difference_ned_m(const StateView& s, double lat_rad, double lon_rad,
                                          double height_m);

// Heading (azimuth from north) of a vehicle-frame direction after rotation into NED, and its
// Jacobian with respect to the attitude error phi.
struct AzimuthModel {
  double azimuth_rad = 0.0;
  Eigen::RowVector3d d_dphi = Eigen::RowVector3d::Zero();
};
AzimuthModel azimuth_of(const StateView& s, const Eigen::Vector3d& direction_b);

// Velocity of a point at `lever_arm_m` in the vehicle frame (optionally in the odometry frame,
// rotated by the residual mounting states) and its Jacobian rows:
//   v = R_m (C_nb^T v_n + w_eb x l),  R_m = I - [alpha x],  alpha = (0, pitch, yaw)
struct BodyVelocityModel {
  Eigen::Vector3d vel_mps = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 3, sx::kCount> jacobian = Eigen::Matrix<double, 3, sx::kCount>::Zero();
};
BodyVelocityModel body_velocity_at(const StateView& s, const Eigen::Vector3d& lever_arm_m,
                                   bool odometry_frame);

}  // namespace navfuse::filter

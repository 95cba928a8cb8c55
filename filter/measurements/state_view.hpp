// What every measurement model reads: the nominal state plus quantities derived from it once per
// update (attitude matrix, compensated angular rate, local earth).
#pragma once

#include <array>
#include <limits>

#include <Eigen/Core>

#include "core/geodesy/wgs84.hpp"
#include "filter/ekf.hpp"
#include "filter/neglected_term.hpp"
#include "filter/nav_state.hpp"
#include "filter/strapdown.hpp"

namespace navfuse::filter {

struct StateView {
  const NavState& x;
  const LocalEarth& earth;
  Eigen::Matrix3d c_nb;
  Eigen::Vector3d rate_b_rps;  // compensated angular rate w_ib, vehicle frame
  // Measurement time minus state time: |shift| below one IMU interval; for odometry, fused at the
  // covariance grid (measurement_kinds.hpp), down to minus one covariance interval.
  double shift_s = 0.0;
  // Kinematic acceleration dv_n/dt of the newest sample (C_nb f + g; Coriolis and transport rate,
  // < 2e-3 m/s^2 at 30 m/s, left out): an input like the rate, for models that shift a velocity in
  // time. Zero unless the caller sets it.
  Eigen::Vector3d accel_ned_mps2 = Eigen::Vector3d::Zero();

  StateView(const NavState& state, const LocalEarth& local, const Eigen::Vector3d& rate, double shift)
      : x(state), earth(local), c_nb(state.q_nb.toRotationMatrix()), rate_b_rps(rate), shift_s(shift) {}
};

// Each model below and in this folder pairs a prediction h(x), a function of the nominal state
// the view is built on (and of the view's compensated rate, itself a function of the state's gyro
// bias and scale), with its Jacobian H = dh/d(dx) in the error convention of state_layout.hpp, so
// that residual = h(x_hat) - z ~= H dx. tests/filter/jacobian_test.cpp differentiates every h
// numerically on states moved with inject_error and compares with H.

// h(x) for a sensor that measures a position (a GNSS antenna, an external aiding source): the
// nominal position moved by the lever arm in NED and by the travel over the time shift.
struct PointPrediction {
  double lat_rad = 0.0, lon_rad = 0.0, height_m = 0.0;    // the nominal position
  Eigen::Vector3d offset_ned_m = Eigen::Vector3d::Zero();  // C_nb l + v shift_s
};
PointPrediction point_at(const StateView& s, const Eigen::Vector3d& lever_arm_m);
// h(x) - z in NED metres at the estimate (locally linear: the residuals are metres to
// kilometres, where the curvature error is far below a millimetre), and h(x) in ECEF.
Eigen::Vector3d point_minus_llh_ned_m(const StateView& s, const PointPrediction& p, double lat_rad,
                                      double lon_rad, double height_m);
Eigen::Vector3d point_ecef_m(const PointPrediction& p);
// H of a point for the position and attitude errors: I and [(C_nb l) x] (C_hat l - C l = [(C l) x] phi).
void point_jacobian(const StateView& s, const Eigen::Vector3d& lever_arm_m, Observation& obs);
inline constexpr std::array<NeglectedTerm, 1> kPointNeglected{{
    {0, 3, sx::kVel, 3, 0.01,
     "velocity error over the time shift, shift_s I: |shift_s| is below one IMU interval (10 ms)"},
}};

// h(x) and H of the heading (azimuth from north) of a vehicle-frame direction after rotation into
// NED, H with respect to the attitude error phi.
struct AzimuthModel {
  double azimuth_rad = 0.0;
  Eigen::RowVector3d d_dphi = Eigen::RowVector3d::Zero();
};
AzimuthModel azimuth_of(const StateView& s, const Eigen::Vector3d& direction_b);

// h(x) and H of the velocity of a point at `lever_arm_m` in the vehicle frame (optionally in the odometry frame,
// rotated by the residual mounting states) and its Jacobian rows:
//   v = R_m (C_nb^T v_n + w_eb x l),  R_m = I - [alpha x],  alpha = (0, pitch, yaw)
struct BodyVelocityModel {
  Eigen::Vector3d vel_mps = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 3, sx::kCount> jacobian = Eigen::Matrix<double, 3, sx::kCount>::Zero();
};
BodyVelocityModel body_velocity_at(const StateView& s, const Eigen::Vector3d& lever_arm_m,
                                   bool odometry_frame);

// Terms the lever-arm rate w x l contributes and H leaves out (bounds for |l| <= 2 m,
// |w| <= 1 rad/s, |s_g| <= 5e-4; the velocity noise they hide under is >= 0.02 m/s).
inline constexpr NeglectedTerm kLeverRateEarthTerm{
    0, 3, sx::kAtt, 3, 2.0 * geo::wgs84::kEarthRate_radps,
    "earth rate in the lever-arm rate turning with attitude, [w_ie x] terms times phi: |w_ie| |l|"};
inline constexpr NeglectedTerm kLeverRateBiasScale{
    0, 3, sx::kGyroBias, 3, 1e-3,
    "the compensation's 1 / (1 + s_g) on the bias taken as 1: |l| |s_g|"};
inline constexpr NeglectedTerm kLeverRateGyroScale{
    0, 3, sx::kGyroScale, 3, std::numeric_limits<double>::infinity(),
    "gyro scale error in the lever-arm rate, [l x] diag(w) ds_g: |l| |w| |ds_g| <= 2e-3 m/s"};
inline constexpr std::array<NeglectedTerm, 3> kBodyVelocityNeglected{
    {kLeverRateEarthTerm, kLeverRateBiasScale, kLeverRateGyroScale}};

}  // namespace navfuse::filter

#include "filter/solution.hpp"

#include <algorithm>
#include <cmath>

#include "core/geodesy/geoid.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::filter {
namespace {

// Status evidence older than this no longer sets its flag.
constexpr double kStatusHold_s = 1.0;
// The std of a heading known to be nothing: uniform over the circle, pi / sqrt(3).
constexpr double kUnknownHeadingStd_rad = 1.8137993642342178;

// Euler-angle errors from the NED attitude error phi: d(roll, pitch, yaw) = M phi, the inverse of
// the Euler-rate relation with the body rates rotated to NED (Titterton & Weston ch. 3). Its
// sines and cosines of yaw and pitch are read off the 3-2-1 DCM itself, C00 = cos p cos y,
// C10 = cos p sin y, C20 = -sin p (Titterton & Weston eq. 3.47), which the fill holds already,
// instead of computing them again from the angles (no difference the replay's time shows).
Eigen::Matrix3d euler_from_phi(const Eigen::Matrix3d& c_nb) {
  const double cp_cy = c_nb(0, 0), cp_sy = c_nb(1, 0), sp = -c_nb(2, 0);
  const double cp = std::max(std::hypot(cp_cy, cp_sy), 1e-6);
  const double cy = cp_cy / cp, sy = cp_sy / cp, tp = sp / cp;
  Eigen::Matrix3d m;
  m << cy / cp, sy / cp, 0.0,
       -sy, cy, 0.0,
       cy * tp, sy * tp, 1.0;
  return m;
}

// The calibration states with their stds, from the captured variances.
void fill_calibration(const StateFieldInputs& in, NavSolution::Calibration& cal) {
  const NavState& x = in.x;
  const StateSelection& states = in.states;
  const auto std_of = [&in](int index) {
    return std::sqrt(std::max(in.calibration_var(index - sx::kCoreCount), 0.0));
  };
  cal.odometer_scale_error = {states.wheel_scale, x.wheel_scale, std_of(sx::kWheelScale)};
  cal.mount_pitch_yaw_rad.estimated = states.mounting;
  cal.mount_pitch_yaw_rad.value = {x.mount_pitch_rad, x.mount_yaw_rad};
  cal.mount_pitch_yaw_rad.std = {std_of(sx::kMountPitch), std_of(sx::kMountYaw)};
  const auto vector3 = [&](NavSolution::Calibration::Vector<3>& v, bool estimated, const Eigen::Vector3d& value,
                           int index) {
    v.estimated = estimated;
    v.value = value;
    v.std = {std_of(index), std_of(index + 1), std_of(index + 2)};
  };
  vector3(cal.gnss_lever_arm_m, states.gnss_lever_arm, x.gnss_lever_arm_m, sx::kLeverArm);
  vector3(cal.gyro_scale, states.gyro_scale, x.gyro_scale, sx::kGyroScale);
  vector3(cal.accel_scale, states.accel_scale, x.accel_scale, sx::kAccelScale);
  cal.gnss_time_offset_s = {states.gnss_time_offset, x.gnss_time_offset_s, std_of(sx::kGnssTimeOffset)};
}

}  // namespace

void capture_state_fields(const NavState& x, const Covariance& p, const Eigen::Vector3d& rate_b_rps,
                          const Eigen::Vector3d& force_b_mps2, const Eigen::Vector3d& gravity_ned_mps2,
                          const Eigen::Matrix3d& c_vs, const StateSelection& states, StateFieldInputs& in) {
  in.x = x;
  in.pos_cov = p.block<3, 3>(sx::kPos, sx::kPos);
  in.vel_cov = p.block<3, 3>(sx::kVel, sx::kVel);
  in.att_cov = p.block<3, 3>(sx::kAtt, sx::kAtt);
  in.gyro_bias_cov = p.block<3, 3>(sx::kGyroBias, sx::kGyroBias);
  in.accel_bias_cov = p.block<3, 3>(sx::kAccelBias, sx::kAccelBias);
  in.c_vs = c_vs;
  in.rate_b_rps = rate_b_rps;
  in.force_b_mps2 = force_b_mps2;
  in.gravity_ned_mps2 = gravity_ned_mps2;

  in.calibration_var = p.diagonal().tail<sx::kCount - sx::kCoreCount>();
  in.states = states;
}

void fill_state_fields(const StateFieldInputs& in, NavSolution& out) {
  const NavState& x = in.x;
  out.lat_rad = x.lat_rad;
  out.lon_rad = x.lon_rad;
  out.height_m = x.height_m;
  if (auto n = geo::egm96_undulation_m(x.lat_rad, x.lon_rad)) {
    out.undulation_m = *n;
    out.header.valid |= NavSolution::kValidUndulation;
  }
  const Eigen::Matrix3d c_nb = x.q_nb.toRotationMatrix();
  out.vel_ned_mps = x.vel_ned_mps;
  out.vel_body_mps = c_nb.transpose() * x.vel_ned_mps;
  out.q_nb = x.q_nb;
  out.rpy_rad = rot::rpy_from_quat(x.q_nb);

  out.pos_std_ned_m = in.pos_cov.diagonal().cwiseMax(0.0).cwiseSqrt();
  out.vel_std_ned_mps = in.vel_cov.diagonal().cwiseMax(0.0).cwiseSqrt();
  const Eigen::Matrix3d m = euler_from_phi(c_nb);
  out.att_std_rpy_rad = (m * in.att_cov * m.transpose()).diagonal().cwiseMax(0.0).cwiseSqrt();

  // Biases are estimated in the vehicle frame and reported in the sensor frame (MIP convention).
  const Eigen::Matrix3d c_sv = in.c_vs.transpose();
  out.gyro_bias_rps = c_sv * x.gyro_bias_rps;
  out.accel_bias_mps2 = c_sv * x.accel_bias_mps2;
  out.gyro_bias_std_rps = (c_sv * in.gyro_bias_cov * c_sv.transpose()).diagonal().cwiseMax(0.0).cwiseSqrt();
  out.accel_bias_std_mps2 = (c_sv * in.accel_bias_cov * c_sv.transpose()).diagonal().cwiseMax(0.0).cwiseSqrt();

  fill_calibration(in, out.calibration);

  out.gravity_ned_mps2 = in.gravity_ned_mps2;
  out.angular_rate_rps = in.rate_b_rps;
  out.linear_accel_mps2 = in.force_b_mps2 + c_nb.transpose() * in.gravity_ned_mps2;
}

void capture_solution(const FilterCore& c, const FilterOptions& o, const Eigen::Matrix3d& c_vs,
                      TimeSource time_source, SolutionInputs& in) {
  const NavState& x = c.x;
  const ModeState& mode = c.mode;
  in.header = MeasurementHeader{};
  in.header.time_ns = x.time_ns;
  in.header.time_source = time_source;
  in.mode = mode.mode;
  in.heading_known = mode.heading_known;
  const bool navigating = mode.mode == NavMode::kNavigation || mode.mode == NavMode::kDeadReckoning;
  // Before the heading is known (vertical gyro) the filter already holds the position of the GNSS
  // fixes (placed at each, place_at_fix) and, moving, their velocity (reset to each) or, at rest,
  // the zero velocity of the ZUPTs: a device reports them then, with the heading marked invalid.
  const bool gnss_current = seconds_since(x.time_ns, c.gnss.last_position_ns) <= o.gnss_timeout_s;
  const bool position_known = navigating || (mode.levelled && mode.position_known && gnss_current);
  const bool velocity_known =
      navigating || (position_known && (c.stationary.stationary ||
                                        seconds_since(x.time_ns, c.gnss.last_velocity_ns) <= o.gnss_timeout_s));
  in.gnss_fix = GnssFixType::kNone;
  if ((mode.mode == NavMode::kNavigation || (!navigating && position_known)) && gnss_current) {
    in.gnss_fix = c.gnss.last_fix;
  }

  capture_state_fields(x, c.ekf.p, c.rate_b_rps, c.force_b_mps2, c.earth.gravity_ned_mps2, c_vs, o.states, in.state);
  apply_output_blend(c.output_blend, in.state.x, in.state.pos_cov);

  if (mode.levelled) {
    in.header.valid |= NavSolution::kValidAttitude | NavSolution::kValidAttitudeStd | NavSolution::kValidBiases;
  }
  if (mode.levelled && mode.heading_known) in.header.valid |= NavSolution::kValidHeading;
  if (position_known) in.header.valid |= NavSolution::kValidPosition | NavSolution::kValidPositionStd;
  if (velocity_known) in.header.valid |= NavSolution::kValidVelocity | NavSolution::kValidVelocityStd;

  in.status_flags = 0;
  if (mode.mode == NavMode::kDeadReckoning) in.status_flags |= NavSolution::kStatusGnssOutage;
  if (c.stationary.stationary) in.status_flags |= NavSolution::kStatusStationary;
  if (mode.diverged) in.status_flags |= NavSolution::kStatusDiverged;
  if (seconds_since(x.time_ns, mode.last_imu_fault_ns) < kStatusHold_s) {
    in.status_flags |= NavSolution::kStatusImuFault;
  }
  if (navigating && seconds_since(x.time_ns, c.odometry.last_speed_ns) < kStatusHold_s) {
    in.status_flags |= NavSolution::kStatusWheelAiding;
  }
  if (seconds_since(x.time_ns, c.gnss.last_heading_ns) < o.gnss_timeout_s) {
    in.status_flags |= NavSolution::kStatusDualAntennaHeading;
  }
  if (c.gnss.baseline.offset_detected) in.status_flags |= NavSolution::kStatusHeadingOffset;
}

void fill_nav_solution(const SolutionInputs& in, NavSolution& out) {
  out = NavSolution{};
  out.header = in.header;
  out.mode = in.mode;
  out.gnss_fix = in.gnss_fix;
  out.status_flags = in.status_flags;
  fill_state_fields(in.state, out);
  // Until the heading is known its error state is held at zero (relative heading, not
  // estimated): the covariance says nothing of it, so report the std of no knowledge at all.
  if (!in.heading_known) out.att_std_rpy_rad.z() = kUnknownHeadingStd_rad;
}

}  // namespace navfuse::filter

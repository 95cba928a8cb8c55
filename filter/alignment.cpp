#include "filter/alignment.hpp"

#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/control/stationary_control.hpp"
#include "filter/measurements/gnss_position.hpp"

namespace navfuse::filter {
namespace {

constexpr double kGravityNominal_mps2 = 9.80665;

void initial_covariance(FilterCore& c, const FilterOptions& o, double tilt_std_rad,
                        double averaging_time_s, bool stationary) {
  Ekf& e = c.ekf;
  e.p.setZero();
  const auto& n = o.imu;
  e.p.block<3, 3>(sx::kPos, sx::kPos).diagonal().setConstant(1e3 * 1e3);  // until a fix
  // At rest the velocity is zero to the ZUPT noise; in motion levelling saw a steady force, which
  // says nothing of the speed: 5 m/s covers a walker or a car creeping through a car park, and the
  // first GNSS velocity or fixes pull it in.
  const double vel_std = o.initial_velocity_std_mps.value_or(stationary ? 0.05 : 5.0);
  e.p.block<3, 3>(sx::kVel, sx::kVel).diagonal().setConstant(vel_std * vel_std);
  e.p.block<3, 3>(sx::kGyroBias, sx::kGyroBias).diagonal().setConstant(
      n.initial_gyro_bias_std_rps * n.initial_gyro_bias_std_rps);
  const double ba_var = n.initial_accel_bias_std_mps2 * n.initial_accel_bias_std_mps2;
  e.p.block<3, 3>(sx::kAccelBias, sx::kAccelBias).diagonal().setConstant(ba_var);
  // An unknown heading is not estimated (vertical-gyro mode): zero variance until it is set.
  const double heading_std = o.initial_heading_rad ? o.initial_heading_std_rad : 0.0;
  e.p(sx::kAttDown, sx::kAttDown) = heading_std * heading_std;
  if (o.initial_tilt_std_rad) {
    // A configured prior (e.g. a platform levelled by other means) replaces the derived one.
    e.p(sx::kAtt, sx::kAtt) = e.p(sx::kAtt + 1, sx::kAtt + 1) = *o.initial_tilt_std_rad * *o.initial_tilt_std_rad;
  } else if (stationary) {
    // Levelling makes C_nb f = (0, 0, -g): the horizontal velocity error rate
    // [f^n x] phi - C_nb d b_a vanishes, so the tilt error is phi_tilt = A d b_a with
    // A = S C_nb / g, S = [[0, -1, 0], [1, 0, 0], [0, 0, 0]]. Its covariance follows the bias
    // prior, plus the accelerometer noise averaged over the levelling time.
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    s(0, 1) = -1.0;
    s(1, 0) = 1.0;
    const Eigen::Matrix3d a = s * c.x.q_nb.toRotationMatrix() / kGravityNominal_mps2;
    const double noise_tilt = n.accel_vrw_mps_rts / std::sqrt(averaging_time_s) / kGravityNominal_mps2;
    e.p.block<3, 3>(sx::kAtt, sx::kAtt).topLeftCorner<2, 2>() =
        (ba_var * a * a.transpose()).topLeftCorner<2, 2>() +
        Eigen::Matrix2d::Identity() * noise_tilt * noise_tilt;
    e.p.block<3, 3>(sx::kAtt, sx::kAccelBias) = ba_var * a;
    e.p.block<3, 3>(sx::kAccelBias, sx::kAtt) = ba_var * a.transpose();
  } else {
    e.p(sx::kAtt, sx::kAtt) = e.p(sx::kAtt + 1, sx::kAtt + 1) = tilt_std_rad * tilt_std_rad;
  }
  const double sf_var = o.initial_wheel_scale_std * o.initial_wheel_scale_std;
  e.p(sx::kWheelScale, sx::kWheelScale) = sf_var;
  const double mount_var = o.initial_mount_std_rad * o.initial_mount_std_rad;
  e.p(sx::kMountPitch, sx::kMountPitch) = e.p(sx::kMountYaw, sx::kMountYaw) = mount_var;
  e.p.block<3, 3>(sx::kLeverArm, sx::kLeverArm).diagonal().setConstant(
      o.initial_lever_arm_std_m * o.initial_lever_arm_std_m);
  e.p(sx::kGnssTimeOffset, sx::kGnssTimeOffset) = o.initial_gnss_time_offset_std_s * o.initial_gnss_time_offset_std_s;
  e.p.block<3, 3>(sx::kGyroScale, sx::kGyroScale).diagonal().setConstant(
      n.initial_gyro_scale_std * n.initial_gyro_scale_std);
  e.p.block<3, 3>(sx::kAccelScale, sx::kAccelScale).diagonal().setConstant(
      n.initial_accel_scale_std * n.initial_accel_scale_std);
  for (int i = 0; i < sx::kCount; ++i) {
    if (o.states.is_active(i)) continue;
    e.p.row(i).setZero();
    e.p.col(i).setZero();
  }
}

}  // namespace

void feed_leveller(FilterCore& c, const FilterOptions& o, const ImuIncrement& raw) {
  Leveller& l = c.leveller;
  l.since_start_s += raw.dt_s;
  l.window_time_s += raw.dt_s;
  l.window_dvel += raw.dvel_mps;
  l.window_dtheta += raw.dtheta_rad;
  l.window_f_sq += (raw.dvel_mps / raw.dt_s).squaredNorm();
  ++l.window_count;
  if (l.window_time_s < o.stationary_window_s) return;

  const Eigen::Vector3d mean_f = l.window_dvel / l.window_time_s;
  const Eigen::Vector3d mean_w = l.window_dtheta / l.window_time_s;
  const double scatter =
      std::sqrt(std::max(0.0, l.window_f_sq / l.window_count - mean_f.squaredNorm()));
  // Levelling needs the specific force to be gravity alone: no acceleration, which a quiet IMU
  // (small rate and specific-force scatter) shows. Engine and road vibration raise the scatter of
  // a standing car far above the quiet threshold (tens of times the data-sheet noise), so two more
  // kinds of evidence count: a speed measurement showing the vehicle at rest (then as good as
  // quiet), and a window mean of the specific force that stays where the previous window's was
  // (the vibration averages out; constant-velocity motion passes too, harmless for the tilt, so
  // the velocity is then not taken as zero).
  const bool rate_quiet = mean_w.norm() < o.stationary_gyro_rps;
  const bool at_rest = rate_quiet && (scatter < o.stationary_accel_std_mps2 || speed_shows_rest(c, o));
  // Against the run's first window, so that a slow ramp of acceleration does not pass.
  const Eigen::Vector3d& reference = l.static_time_s > 0.0 ? l.run_reference_force : l.previous_mean_force;
  const bool steady = rate_quiet && l.have_previous_mean &&
                      (mean_f - reference).norm() < 2.0 * o.stationary_accel_std_mps2;
  l.have_previous_mean = true;
  l.previous_mean_force = mean_f;
  if (at_rest || steady) {
    if (l.static_time_s == 0.0) {
      l.run_at_rest = true;
      l.run_reference_force = mean_f;
    }
    l.run_at_rest = l.run_at_rest && at_rest;
    l.static_time_s += l.window_time_s;
    l.dvel_sum += l.window_dvel;
    l.dtheta_sum += l.window_dtheta;
  } else {
    l.static_time_s = 0.0;
    l.dvel_sum.setZero();
    l.dtheta_sum.setZero();
  }
  const double window_time = l.window_time_s;
  l.window_time_s = 0.0;
  l.window_dvel.setZero();
  l.window_dtheta.setZero();
  l.window_f_sq = 0.0;
  l.window_count = 0;

  if (l.static_time_s >= o.level_time_s) {
    level(c, o, l.dvel_sum / l.static_time_s, l.static_time_s, l.run_at_rest);
  } else if (l.since_start_s >= o.level_timeout_s) {
    level(c, o, mean_f, window_time, false);
  }
}

void level(FilterCore& c, const FilterOptions& o, const Eigen::Vector3d& f, double averaging_time_s,
           bool stationary) {
  // f_b = -C_bn g_n = g (sin(theta), -sin(phi) cos(theta), -cos(phi) cos(theta)) for FRD.
  const double roll = std::atan2(-f.y(), -f.z());
  const double pitch = std::atan2(f.x(), std::hypot(f.y(), f.z()));
  const double yaw = o.initial_heading_rad.value_or(0.0);
  c.x.q_nb = rot::quat_from_rpy(Eigen::Vector3d(roll, pitch, yaw));
  c.x.vel_ned_mps.setZero();
  initial_covariance(c, o, 2.0 * rot::kDegToRad, averaging_time_s, stationary);
  c.memory = StrapdownMemory{};
  c.step = ProcessAccumulator{};
  c.mode.levelled = true;
  c.mode.heading_known = o.initial_heading_rad.has_value();
  if (c.gnss.have_fix) place_at_fix(c, o, c.gnss.latest_fix);
  c.earth = LocalEarth::at(c.x.lat_rad, c.x.height_m);
}

void set_heading(FilterCore& c, double yaw_rad, double std_rad) {
  const Eigen::Vector3d rpy = rot::rpy_from_quat(c.x.q_nb);
  c.x.q_nb = rot::quat_from_rpy(Eigen::Vector3d(rpy.x(), rpy.y(), yaw_rad));
  // Roll and pitch errors belong to the vehicle, so their NED components turn with the heading:
  // phi_h' = Rz(d_psi) phi_h. Transform the attitude rows and columns of P accordingly.
  const Eigen::Matrix3d r = rot::dcm_from_rpy(Eigen::Vector3d(0.0, 0.0, rot::wrap_pi(yaw_rad - rpy.z())));
  const int n = c.ekf.n;
  c.ekf.p.block(sx::kAtt, 0, 3, n) = (r * c.ekf.p.block(sx::kAtt, 0, 3, n)).eval();
  c.ekf.p.block(0, sx::kAtt, n, 3) = (c.ekf.p.block(0, sx::kAtt, n, 3) * r.transpose()).eval();
  c.ekf.reset_states(sx::kAttDown, 1, std_rad * std_rad);
  if (!c.mode.heading_known) {
    // With the wrong heading the horizontal earth rate was removed in the wrong direction, and
    // the gyro-bias estimate absorbed the difference (up to 2 w_ie cos(lat)): widen it by that.
    const double w = 2.0 * c.earth.earth_rate_ned_rps.head<2>().norm();
    c.ekf.p.block<3, 3>(sx::kGyroBias, sx::kGyroBias).diagonal().array() += w * w;
  }
  c.mode.heading_known = true;
}

void place_at_fix(FilterCore& c, const FilterOptions& o, const GnssPosition& fix) {
  const Eigen::Vector3d lever_b =
      antenna_of_receiver(c.x, o.gnss_secondary_lever_arm_m, fix.receiver_id).lever_arm_m;
  const Eigen::Matrix3d c_nb = c.x.q_nb.toRotationMatrix();
  const Eigen::Vector3d lever_n = c_nb * lever_b;
  // The fix is older than the state by (state time - fix time): move along the velocity.
  const double age_s = static_cast<double>(c.x.time_ns - fix.header.time_ns) * 1e-9;
  const geo::Llh antenna{fix.lat_rad, fix.lon_rad, fix.height_m};
  const geo::Llh ref = geo::llh_offset(antenna, -lever_n + c.x.vel_ned_mps * age_s);
  c.x.lat_rad = ref.lat_rad;
  c.x.lon_rad = ref.lon_rad;
  if ((fix.header.valid & GnssPosition::kValidHeight) != 0) c.x.height_m = ref.height_m;
  Eigen::Matrix3d cov = gnss_position_cov_m2(fix, o.gnss_position_std_scale_for(fix.fix));
  if (!c.mode.heading_known) {
    const double lever_h_sq = lever_b.head<2>().squaredNorm();
    cov(0, 0) += lever_h_sq;
    cov(1, 1) += lever_h_sq;
  }
  if ((fix.header.valid & GnssPosition::kValidHeight) == 0) cov(2, 2) = 100.0 * 100.0;
  c.ekf.reset_states(sx::kPos, cov);
  c.mode.position_known = true;
  c.mode.last_absolute_position_ns = fix.header.time_ns;
  c.earth = LocalEarth::at(c.x.lat_rad, c.x.height_m);
}

}  // namespace navfuse::filter

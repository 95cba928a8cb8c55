#include "filter/control/stationary_control.hpp"

#include <cmath>

#include "filter/measurements/zero_velocity.hpp"

namespace navfuse::filter {
namespace {

// Evidence older than this is not used to decide whether the vehicle moves.
constexpr double kSpeedEvidenceAge_s = 0.5;

bool speed_evidence_allows_rest(const FilterCore& c, const FilterOptions& o) {
  const double limit = o.stationary_max_speed_mps;
  if (seconds_since(c.x.time_ns, c.odometry.last_speed_ns) < kSpeedEvidenceAge_s) {
    return std::abs(c.odometry.last_speed_mps) < limit;
  }
  if (seconds_since(c.x.time_ns, c.gnss.last_speed_ns) < kSpeedEvidenceAge_s &&
      c.gnss.last_speed_mps >= limit) {
    return false;
  }
  if (c.navigating()) return c.x.vel_ned_mps.norm() < 2.0 * limit;
  return true;
}

}  // namespace

bool speed_shows_rest(const FilterCore& c, const FilterOptions& o) {
  const double limit = 0.5 * o.stationary_max_speed_mps;
  if (seconds_since(c.x.time_ns, c.odometry.last_speed_ns) < kSpeedEvidenceAge_s) {
    return std::abs(c.odometry.last_speed_mps) < limit;
  }
  return seconds_since(c.x.time_ns, c.gnss.last_speed_ns) < kSpeedEvidenceAge_s && c.gnss.last_speed_mps < limit;
}

void update_stationary(FilterCore& c, const FilterOptions& o, const ImuIncrement& raw) {
  StationaryState& s = c.stationary;
  s.window_time_s += raw.dt_s;
  ++s.window_count;
  s.sum_rate += raw.dtheta_rad;
  s.sum_force += raw.dvel_mps;
  s.sum_force_sq += (raw.dvel_mps / raw.dt_s).squaredNorm();
  s.sum_rate_sq += (raw.dtheta_rad / raw.dt_s).squaredNorm();
  if (s.window_time_s < o.stationary_window_s) return;

  const double t = s.window_time_s;
  const Eigen::Vector3d mean_raw_rate = s.sum_rate / t;
  const Eigen::Vector3d mean_force = s.sum_force / t;
  const double scatter = std::sqrt(std::max(0.0, s.sum_force_sq / s.window_count - mean_force.squaredNorm()));
  const Eigen::Vector3d mean_rate = mean_raw_rate - c.x.gyro_bias_rps;
  const bool force_steady = !s.stationary || (mean_force - s.reference_force).norm() < 2.0 * o.stationary_accel_std_mps2;
  // An idling engine shakes a standing car far above the quiet scatter (car_vibration: 0.1 m/s^2
  // RMS at idle, twice the default threshold), so a fresh speed measurement at rest stands in for
  // it, as it does for levelling (alignment.cpp). Without it a car that stands for minutes before
  // it drives gets no zero-velocity or zero-rate update: its tilt drifts on the gyro biases
  // (2.8 deg after 200 s on parking_drive's IMU) and the heading found when it moves off is
  // 22 deg wrong.
  const bool force_quiet = scatter < o.stationary_accel_std_mps2 || speed_shows_rest(c, o);
  const bool quiet = mean_rate.norm() < o.stationary_gyro_rps && force_quiet && force_steady;
  const bool was_stationary = s.stationary;
  s.stationary = quiet && s.previous_quiet && speed_evidence_allows_rest(c, o);
  if (s.stationary && !was_stationary) s.reference_force = mean_force;
  s.previous_quiet = quiet;
  const int samples = s.window_count;
  s.window_time_s = 0.0;
  s.window_count = 0;
  s.sum_rate.setZero();
  s.sum_force.setZero();
  s.sum_force_sq = 0.0;
  const double rate_sq = s.sum_rate_sq;
  s.sum_rate_sq = 0.0;
  if (!s.stationary || !o.zero_velocity_updates) return;

  const Observation zero_velocity = zero_velocity_observation(c.view(0.0), o.zupt_std_mps);
  const FuseResult zupt = c.apply(o, zero_velocity, o.gate_for(GatedAid::kStationary, zero_velocity.rows()));
  if (zupt.used) {
    ++c.mode.zupts;
  } else if (!c.navigating() && zupt.reason == RejectReason::kChi2Gate) {
    // Without position or velocity aiding (vertical-gyro and AHRS modes) the velocity is integrated
    // tilt error and noise: on the shared MicroStrain capture it reached 10 m/s within a minute of
    // hand motion, and every later stop was rejected at the gate, leaving the tilt to drift. A stop
    // is the first evidence of what the velocity is: restart it there, at the update's std.
    c.x.vel_ned_mps.setZero();
    c.ekf.reset_states(sx::kVel, 3, o.zupt_std_mps * o.zupt_std_mps);
    ++c.mode.zupts;
  }
  // The window mean of white rate noise has std ARW / sqrt(T); the bias random walk within the
  // window is negligible next to it. Vibration adds rate noise far above the data sheet's: the
  // window's own scatter over sqrt(n) (per axis: the |rate|^2 scatter over 3) is then the standard
  // error of its mean, if larger.
  const double rate_scatter_sq = std::max(0.0, rate_sq / samples - mean_raw_rate.squaredNorm()) / 3.0;
  double std_rps = std::max(o.imu.gyro_arw_rad_rts / std::sqrt(t), std::sqrt(rate_scatter_sq / samples));
  if (!c.mode.heading_known) {
    // Before the heading is known the horizontal earth rate's direction in the body is unknown
    // (its magnitude, w_ie cos(lat), is not): count it as noise, so the gyro biases still settle
    // to ~15 deg/h at the first stop instead of waiting for a heading (MEMS turn-on biases are
    // hundreds of deg/h, enough to tilt the levelling by a degree in ten seconds).
    const double horizontal_earth_rate = c.earth.earth_rate_ned_rps.head<2>().norm();
    std_rps = std::hypot(std_rps, horizontal_earth_rate);
  }
  const Observation zero_rate = zero_rate_observation(c.view(0.0), mean_raw_rate, std_rps);
  c.apply(o, zero_rate, o.gate_for(GatedAid::kStationary, zero_rate.rows()));
}

}  // namespace navfuse::filter

#include "apps/simcmd/device_solution_model.hpp"

#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/geodesy/gravity.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

constexpr double kDeg = rot::kDegToRad;
// Its own random stream, distinct from the simulator's sensor streams (apps/sim/random.hpp), so
// adding a device solution changes none of the simulated measurements.
constexpr auto kDeviceStream = static_cast<sim::RandomStream>(0xDE71CE);
// GNSS back: the dead-reckoning error is pulled back to the aided level with this time constant.
constexpr double kRecoveryTimeS = 5.0;

// One exact Gauss-Markov step for each component.
void gauss_markov(Eigen::Vector3d& e, const Eigen::Vector3d& sigma, double dt_s, double tau_s, sim::Rng& rng) {
  const double phi = std::exp(-dt_s / tau_s);
  const double q = std::sqrt(1.0 - phi * phi);
  for (int i = 0; i < 3; ++i) e[i] = phi * e[i] + q * sigma[i] * rng.normal();
}

}  // namespace

DeviceErrorClass device_error_class(const frontends::FrontendInfo& frontend, double imu_rate_hz) {
  DeviceErrorClass c = frontend.device_errors;
  if (c.rate_is_imu_rate) c.rate_hz = imu_rate_hz;
  return c;
}

DeviceSolutionModel::DeviceSolutionModel(const DeviceErrorClass& errors, std::int64_t start_time_ns, std::uint64_t seed)
    : c_(errors),
      start_ns_(start_time_ns),
      period_ns_(static_cast<std::int64_t>(std::llround(1e9 / errors.rate_hz))),
      last_ns_(start_time_ns),
      rng_(seed, kDeviceStream) {
  // Start from the stationary distribution, as a device that has been running a while.
  const Eigen::Vector3d pos_sigma(c_.horizontal_std_m, c_.horizontal_std_m, c_.vertical_std_m);
  const Eigen::Vector3d att_sigma(c_.roll_pitch_std_rad, c_.roll_pitch_std_rad, c_.heading_std_rad);
  for (int i = 0; i < 3; ++i) {
    pos_err_m_[i] = pos_sigma[i] * rng_.normal();
    vel_err_mps_[i] = c_.velocity_std_mps * rng_.normal();
    att_err_rad_[i] = att_sigma[i] * rng_.normal();
  }
}

void DeviceSolutionModel::propagate(double dt_s, bool gnss) {
  const Eigen::Vector3d pos_sigma(c_.horizontal_std_m, c_.horizontal_std_m, c_.vertical_std_m);
  const Eigen::Vector3d att_sigma(c_.roll_pitch_std_rad, c_.roll_pitch_std_rad, c_.heading_std_rad);
  gauss_markov(pos_err_m_, pos_sigma, dt_s, c_.position_corr_time_s, rng_);
  gauss_markov(vel_err_mps_, Eigen::Vector3d::Constant(c_.velocity_std_mps), dt_s, c_.velocity_corr_time_s, rng_);
  gauss_markov(att_err_rad_, att_sigma, dt_s, c_.attitude_corr_time_s, rng_);
  if (!gnss) {
    if (!in_outage_) {
      for (int i = 0; i < 3; ++i) outage_accel_mps2_[i] = c_.outage_accel_std_mps2 * rng_.normal();
      in_outage_ = true;
      outage_s_ = 0.0;
    }
    outage_s_ += dt_s;
    drift_pos_m_ += drift_vel_mps_ * dt_s + 0.5 * outage_accel_mps2_ * dt_s * dt_s;
    drift_vel_mps_ += outage_accel_mps2_ * dt_s;
  } else {
    in_outage_ = false;
    const double decay = std::exp(-dt_s / kRecoveryTimeS);
    drift_pos_m_ *= decay;
    drift_vel_mps_ *= decay;
    outage_s_ *= decay;
  }
}

bool DeviceSolutionModel::step(const sim::TruthSample& truth, NavSolution& out) {
  const double dt_s = static_cast<double>(truth.time_ns - last_ns_) * 1e-9;
  last_ns_ = truth.time_ns;
  if (dt_s > 0.0) propagate(dt_s, truth.gnss_available);
  if ((truth.time_ns - start_ns_) % period_ns_ != 0) return false;

  out = NavSolution{};
  out.header.time_ns = truth.time_ns;
  out.header.time_source = TimeSource::kGps;
  const bool aligned = static_cast<double>(truth.time_ns - start_ns_) * 1e-9 >= c_.alignment_s;
  if (!aligned) {
    out.mode = NavMode::kInitializing;
    return true;
  }
  out.mode = truth.gnss_available ? NavMode::kNavigation : NavMode::kDeadReckoning;
  out.gnss_fix = truth.gnss_available ? GnssFixType::kFix3D : GnssFixType::kNone;
  if (!truth.gnss_available) out.status_flags |= NavSolution::kStatusGnssOutage;
  if (truth.stationary) out.status_flags |= NavSolution::kStatusStationary;

  const Eigen::Vector3d pos_err = pos_err_m_ + drift_pos_m_;
  const geo::Llh llh = geo::llh_offset(truth.llh, pos_err);
  out.lat_rad = llh.lat_rad;
  out.lon_rad = llh.lon_rad;
  out.height_m = llh.height_m;
  out.vel_ned_mps = truth.vel_ned_mps + vel_err_mps_ + drift_vel_mps_;
  out.rpy_rad = truth.rpy_rad + att_err_rad_;
  out.rpy_rad.z() = rot::wrap_pi(out.rpy_rad.z());
  out.q_nb = rot::quat_from_rpy(out.rpy_rad);
  out.vel_body_mps = out.q_nb.conjugate() * out.vel_ned_mps;

  // Reported 1-sigma: the aided level plus the dead-reckoning growth 1/2 sigma_a t^2.
  const double t = outage_s_;
  const double drift_pos = 0.5 * c_.outage_accel_std_mps2 * t * t;
  const double drift_vel = c_.outage_accel_std_mps2 * t;
  out.pos_std_ned_m = Eigen::Vector3d(c_.horizontal_std_m, c_.horizontal_std_m, c_.vertical_std_m).array() + drift_pos;
  out.vel_std_ned_mps = Eigen::Vector3d::Constant(c_.velocity_std_mps + drift_vel);
  out.att_std_rpy_rad = Eigen::Vector3d(c_.roll_pitch_std_rad, c_.roll_pitch_std_rad, c_.heading_std_rad);

  // Biases: the device's estimate is the true bias (vehicle frame here; the simulated mounting is
  // identity in the demo scenarios) to within its own uncertainty.
  out.gyro_bias_rps = truth.gyro_bias_vehicle_rps;
  out.accel_bias_mps2 = truth.accel_bias_vehicle_mps2;
  out.gyro_bias_std_rps = Eigen::Vector3d::Constant(1.0 * kDeg / 3600.0);
  out.accel_bias_std_mps2 = Eigen::Vector3d::Constant(1e-3);
  out.angular_rate_rps = truth.omega_ib_b_rps;
  out.gravity_ned_mps2 = geo::normal_gravity_ned(truth.llh.lat_rad, truth.llh.height_m);
  out.linear_accel_mps2 = truth.q_nb.conjugate() * truth.accel_ned_mps2;

  out.header.valid = NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidAttitude |
                     NavSolution::kValidPositionStd | NavSolution::kValidVelocityStd |
                     NavSolution::kValidAttitudeStd | NavSolution::kValidBiases | NavSolution::kValidHeading;
  return true;
}

}  // namespace navfuse::apps

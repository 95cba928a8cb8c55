// Simulated GNSS receiver (see gnss_model.hpp for the noise model).
#include "apps/sim/gnss_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::sim {

GnssNoise default_gnss_noise(GnssFixType fix) {
  // Typical 1-sigma receiver figures (open sky): position per axis, velocity per axis.
  GnssNoise n;
  switch (fix) {
    case GnssFixType::kRtkFixed:
      n = {0.02, 0.03, 0.0, 60.0, 0.02, 0.03, 20};
      break;
    case GnssFixType::kRtkFloat:
      n = {0.3, 0.5, 0.0, 60.0, 0.03, 0.05, 18};
      break;
    case GnssFixType::kPpp:
      n = {0.1, 0.2, 0.0, 60.0, 0.03, 0.05, 18};
      break;
    case GnssFixType::kDgnss:
    case GnssFixType::kSbas:
      n = {0.5, 1.0, 0.0, 60.0, 0.05, 0.1, 12};
      break;
    case GnssFixType::kFix2D:
      n = {3.0, 10.0, 0.0, 60.0, 0.1, 0.2, 4};
      break;
    default:  // kFix3D and anything a receiver would call a plain fix
      n = {1.5, 3.0, 0.0, 60.0, 0.05, 0.1, 10};
      break;
  }
  return n;
}

GnssNoise receiver_fix_noise(GnssFixType fix) {
  GnssNoise n = default_gnss_noise(fix);
  switch (fix) {
    case GnssFixType::kRtkFixed:
      n.correlated_fraction = 0.0;
      break;
    case GnssFixType::kRtkFloat:
    case GnssFixType::kPpp:
      n.correlated_fraction = 0.9;
      n.correlation_time_s = 60.0;
      break;
    case GnssFixType::kDgnss:
    case GnssFixType::kSbas:
      n.correlated_fraction = 0.8;
      n.correlation_time_s = 60.0;
      break;
    default:
      n.correlated_fraction = 0.8;
      n.correlation_time_s = 120.0;
      break;
  }
  return n;
}

GnssSpec gnss_standalone(double rate_hz) {
  GnssSpec s;
  s.rate_hz = rate_hz;
  s.fix = GnssFixType::kFix3D;
  s.noise = default_gnss_noise(s.fix);
  return s;
}

GnssSpec gnss_rtk_fixed(double rate_hz) {
  GnssSpec s;
  s.rate_hz = rate_hz;
  s.fix = GnssFixType::kRtkFixed;
  s.noise = default_gnss_noise(s.fix);
  return s;
}

geo::Llh lever_arm_position(const TruthSample& truth, const Eigen::Vector3d& lever_arm_m) {
  return geo::llh_offset(truth.llh, truth.q_nb * lever_arm_m);
}

Eigen::Vector3d lever_arm_velocity_ned(const TruthSample& truth, const Eigen::Vector3d& lever_arm_m) {
  const Eigen::Vector3d omega_ie_b =
      truth.q_nb.conjugate() * geo::earth_rate_ned(truth.llh.lat_rad);
  const Eigen::Vector3d omega_eb_b = truth.omega_ib_b_rps - omega_ie_b;
  return truth.vel_ned_mps + truth.q_nb * omega_eb_b.cross(lever_arm_m);
}

GnssModel::GnssModel(const GnssSpec& spec, std::uint64_t seed)
    : spec_(spec),
      rng_(seed, RandomStream::kGnss),
      heading_rng_(seed, RandomStream::kHeading),
      multipath_(multipath_events(spec.multipath, seed)) {
  if (spec_.enabled) {
    if (!(spec_.rate_hz > 0.0) || !std::isfinite(spec_.rate_hz)) {
      throw std::invalid_argument("gnss.rate_hz must be positive");
    }
    const double period_ns = 1e9 / spec_.rate_hz;
    period_ns_ = static_cast<std::int64_t>(std::llround(period_ns));
    if (std::abs(period_ns - static_cast<double>(period_ns_)) > 1e-3) {
      throw std::invalid_argument("gnss.rate_hz: the period must be a whole number of nanoseconds");
    }
  }
  if (spec_.latency_s < 0.0) throw std::invalid_argument("gnss.latency_s must not be negative");
  latency_ns_ = time::nanoseconds(spec_.latency_s);
  // The correlated error starts in its stationary distribution.
  gm_unit_ = Eigen::Vector3d(rng_.normal(), rng_.normal(), rng_.normal());
}

bool GnssModel::available(double t_s) const {
  if (!spec_.enabled) return false;
  for (const TimeInterval& outage : spec_.outages) {
    if (outage.contains(t_s)) return false;
  }
  return true;
}

const GnssNoise& GnssModel::noise_at(double t_s, GnssFixType* fix) const {
  for (const GnssFixInterval& f : spec_.fix_schedule) {
    if (f.interval.contains(t_s)) {
      if (fix) *fix = f.fix;
      return f.noise;
    }
  }
  if (fix) *fix = spec_.fix;
  return spec_.noise;
}

GnssModel::Epoch GnssModel::make_epoch(const TruthSample& truth, double t_s, GnssPosition& pos,
                                       GnssVelocity& vel, GnssHeading& heading) {
  Epoch epoch;
  if (!available(t_s)) return epoch;  // the correlated error catches up at the next fix

  GnssFixType fix = GnssFixType::kNone;
  const GnssNoise& noise = noise_at(t_s, &fix);

  // Advance the unit-variance Gauss-Markov state over the time since the last fix (exact for any
  // gap, so outages do not distort its statistics).
  const double gap_s = have_last_epoch_ ? time::seconds(truth.time_ns - last_epoch_ns_) : 0.0;
  const double phi = noise.correlation_time_s > 0.0 ? std::exp(-gap_s / noise.correlation_time_s) : 0.0;
  const double drive = std::sqrt(1.0 - phi * phi);
  for (int i = 0; i < 3; ++i) gm_unit_[i] = phi * gm_unit_[i] + drive * rng_.normal();
  last_epoch_ns_ = truth.time_ns;
  have_last_epoch_ = true;

  // Every epoch draws the same count of random numbers whatever is switched on, so that the
  // noise of later epochs does not depend on glitch settings.
  const Eigen::Vector3d white(rng_.normal(), rng_.normal(), rng_.normal());
  const Eigen::Vector3d vel_white(rng_.normal(), rng_.normal(), rng_.normal());
  const double glitch_draw = rng_.uniform();
  const double glitch_azimuth = 2.0 * rot::kPi * rng_.uniform();

  const Eigen::Vector3d sigma(noise.horizontal_std_m, noise.horizontal_std_m, noise.vertical_std_m);
  const double c = std::clamp(noise.correlated_fraction, 0.0, 1.0);
  Eigen::Vector3d offset_ned =
      sigma.cwiseProduct(std::sqrt(c) * gm_unit_ + std::sqrt(1.0 - c) * white);
  if (glitch_draw < spec_.glitch_fraction) {
    offset_ned += spec_.glitch_offset_m *
                  Eigen::Vector3d(std::cos(glitch_azimuth), std::sin(glitch_azimuth), 0.0);
    epoch.glitched = true;
  }
  for (const GnssJump& jump : spec_.jumps) {
    if (t_s >= jump.time_s) offset_ned += jump.offset_ned_m;
  }
  offset_ned += multipath_offset(multipath_, t_s, &epoch.multipath);

  const geo::Llh antenna = lever_arm_position(truth, spec_.lever_arm_m);
  const geo::Llh reported = geo::llh_offset(antenna, offset_ned);
  pos = GnssPosition{};
  pos.header.time_ns = truth.time_ns;
  pos.header.time_source = TimeSource::kGps;
  pos.header.valid =
      GnssPosition::kValidPosition | GnssPosition::kValidHeight | GnssPosition::kValidCovariance;
  pos.lat_rad = reported.lat_rad;
  pos.lon_rad = reported.lon_rad;
  pos.height_m = reported.height_m;
  pos.cov_ned_m2 = sigma.cwiseAbs2().asDiagonal();
  pos.fix = fix;
  pos.num_sats = noise.num_sats;
  pos.receiver_id = spec_.receiver_id;
  epoch.has_position = true;

  if (spec_.velocity) {
    const Eigen::Vector3d vel_sigma(noise.horizontal_velocity_std_mps,
                                    noise.horizontal_velocity_std_mps,
                                    noise.vertical_velocity_std_mps);
    vel = GnssVelocity{};
    vel.header = pos.header;
    vel.header.valid = GnssVelocity::kValidVelocity | GnssVelocity::kValidCovariance;
    vel.vel_ned_mps =
        lever_arm_velocity_ned(truth, spec_.lever_arm_m) + vel_sigma.cwiseProduct(vel_white);
    vel.cov_ned_m2ps2 = vel_sigma.cwiseAbs2().asDiagonal();
    vel.fix = fix;
    vel.receiver_id = spec_.receiver_id;
    epoch.has_velocity = true;
  }

  if (spec_.heading) {
    const double heading_noise = heading_rng_.normal();
    const double pitch_noise = heading_rng_.normal();
    const Eigen::Vector3d baseline_ned =
        truth.q_nb * (spec_.secondary_lever_arm_m - spec_.lever_arm_m);
    heading = GnssHeading{};
    heading.header = pos.header;
    heading.header.valid =
        GnssHeading::kValidHeading | GnssHeading::kValidPitch | GnssHeading::kValidBaseline;
    heading.heading_rad = rot::wrap_pi(std::atan2(baseline_ned.y(), baseline_ned.x()) +
                                       spec_.heading_std_rad * heading_noise);
    heading.heading_std_rad = spec_.heading_std_rad;
    heading.pitch_rad = std::atan2(-baseline_ned.z(), baseline_ned.head<2>().norm()) +
                        spec_.heading_pitch_std_rad * pitch_noise;
    heading.pitch_std_rad = spec_.heading_pitch_std_rad;
    heading.baseline_m = baseline_ned.norm();
    heading.fix = fix;
    epoch.has_heading = true;
  }
  return epoch;
}

}  // namespace navfuse::sim

// Simulated wheel odometry (see wheel_model.hpp for the model).
#include "apps/sim/wheel_model.hpp"

#include <cmath>
#include <stdexcept>

#include "core/geodesy/geodesy.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::sim {

Eigen::Vector3d point_velocity_vehicle(const TruthSample& truth, const Eigen::Vector3d& lever_arm_m) {
  const Eigen::Quaterniond q_bn = truth.q_nb.conjugate();
  const Eigen::Vector3d omega_eb_b =
      truth.omega_ib_b_rps - q_bn * geo::earth_rate_ned(truth.llh.lat_rad);
  return q_bn * truth.vel_ned_mps + omega_eb_b.cross(lever_arm_m);
}

WheelModel::WheelModel(const WheelSpec& spec, std::uint64_t seed)
    : spec_(spec), rng_(seed, RandomStream::kWheel) {
  if (enabled()) {
    if (!(spec_.rate_hz > 0.0) || !std::isfinite(spec_.rate_hz)) {
      throw std::invalid_argument("wheel.rate_hz must be positive");
    }
    const double period_ns = 1e9 / spec_.rate_hz;
    period_ns_ = static_cast<std::int64_t>(std::llround(period_ns));
    if (std::abs(period_ns - static_cast<double>(period_ns_)) > 1e-3) {
      throw std::invalid_argument("wheel.rate_hz: the period must be a whole number of nanoseconds");
    }
  }
  if (spec_.latency_s < 0.0) throw std::invalid_argument("wheel.latency_s must not be negative");
  latency_ns_ = time::nanoseconds(spec_.latency_s);
}

Gear WheelModel::gear_for(double speed_mps) {
  // Standing still keeps the last gear (a stop in traffic is not "park").
  if (speed_mps > 0.0) last_gear_ = Gear::kForward;
  if (speed_mps < 0.0) last_gear_ = Gear::kReverse;
  return last_gear_;
}

double WheelModel::measure(double true_speed_mps) {
  const double w = rng_.normal();  // drawn always: the stream does not depend on the motion
  if (true_speed_mps == 0.0) return 0.0;
  const double v = (1.0 + spec_.scale_error) * true_speed_mps + spec_.noise_std_mps * w;
  return spec_.is_signed ? v : std::abs(v);
}

void WheelModel::make_vehicle_speed(const TruthSample& truth, VehicleSpeed& out) {
  const double true_speed = truth.stationary ? 0.0 : point_velocity_vehicle(truth, spec_.lever_arm_m).x();
  out = VehicleSpeed{};
  out.header.time_ns = truth.time_ns;
  out.header.time_source = TimeSource::kGps;
  out.header.valid = VehicleSpeed::kValidSpeed;
  out.speed_mps = measure(true_speed);
  out.gear = gear_for(truth.speed_mps);
  out.is_signed = spec_.is_signed;
  out.speed_std_mps = spec_.reported_std_mps > 0.0 ? spec_.reported_std_mps : spec_.noise_std_mps;
}

void WheelModel::make_wheel_speeds(const TruthSample& truth, WheelSpeeds& out) {
  // Contact points: FL, FR, RL, RR (core order), the rear pair centred on lever_arm_m.
  const double half_track = 0.5 * spec_.track_m;
  const Eigen::Vector3d offsets[4] = {{spec_.wheelbase_m, -half_track, 0.0},
                                      {spec_.wheelbase_m, half_track, 0.0},
                                      {0.0, -half_track, 0.0},
                                      {0.0, half_track, 0.0}};
  out = WheelSpeeds{};
  out.header.time_ns = truth.time_ns;
  out.header.time_source = TimeSource::kGps;
  out.header.valid = WheelSpeeds::kValidFrontLeft | WheelSpeeds::kValidFrontRight |
                     WheelSpeeds::kValidRearLeft | WheelSpeeds::kValidRearRight;
  for (int i = 0; i < 4; ++i) {
    double true_speed = 0.0;
    if (!truth.stationary) {
      const Eigen::Vector3d v = point_velocity_vehicle(truth, spec_.lever_arm_m + offsets[i]);
      true_speed = std::copysign(v.head<2>().norm(), v.x());
    }
    out.speed_mps[static_cast<std::size_t>(i)] = measure(true_speed);
  }
  out.gear = gear_for(truth.speed_mps);
  out.is_signed = spec_.is_signed;
  out.speed_std_mps = spec_.reported_std_mps > 0.0 ? spec_.reported_std_mps : spec_.noise_std_mps;
}

}  // namespace navfuse::sim

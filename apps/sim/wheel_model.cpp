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
  const double true_speed = true_point_speed(truth);
  out = VehicleSpeed{};
  out.header.time_ns = truth.time_ns;
  out.header.time_source = TimeSource::kGps;
  out.header.valid = VehicleSpeed::kValidSpeed;
  out.speed_mps = measure(true_speed);
  out.gear = gear_for(truth.speed_mps);
  out.is_signed = spec_.is_signed;
  out.speed_std_mps = spec_.reported_std_mps > 0.0 ? spec_.reported_std_mps : spec_.noise_std_mps;
}

std::array<double, 4> WheelModel::true_wheel_speeds(const TruthSample& truth) const {
  // Contact points: FL, FR, RL, RR (core order), the rear pair centred on lever_arm_m.
  const double half_track = 0.5 * spec_.track_m;
  const Eigen::Vector3d offsets[4] = {{spec_.wheelbase_m, -half_track, 0.0},
                                      {spec_.wheelbase_m, half_track, 0.0},
                                      {0.0, -half_track, 0.0},
                                      {0.0, half_track, 0.0}};
  std::array<double, 4> speeds{};
  if (truth.stationary) return speeds;
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector3d v = point_velocity_vehicle(truth, spec_.lever_arm_m + offsets[i]);
    speeds[i] = std::copysign(v.head<2>().norm(), v.x());
  }
  return speeds;
}

double WheelModel::true_point_speed(const TruthSample& truth) const {
  return truth.stationary ? 0.0 : point_velocity_vehicle(truth, spec_.lever_arm_m).x();
}

void WheelModel::make_wheel_speeds(const TruthSample& truth, WheelSpeeds& out) {
  out = WheelSpeeds{};
  out.header.time_ns = truth.time_ns;
  out.header.time_source = TimeSource::kGps;
  out.header.valid = WheelSpeeds::kValidFrontLeft | WheelSpeeds::kValidFrontRight |
                     WheelSpeeds::kValidRearLeft | WheelSpeeds::kValidRearRight;
  const std::array<double, 4> speeds = true_wheel_speeds(truth);
  for (std::size_t i = 0; i < 4; ++i) out.speed_mps[i] = measure(speeds[i]);
  out.gear = gear_for(truth.speed_mps);
  out.is_signed = spec_.is_signed;
  out.speed_std_mps = spec_.reported_std_mps > 0.0 ? spec_.reported_std_mps : spec_.noise_std_mps;
}

void WheelModel::advance_ticks(const TruthSample& truth) {
  const std::array<double, 4> wheels = true_wheel_speeds(truth);
  const std::array<double, 5> speeds{wheels[0], wheels[1], wheels[2], wheels[3], true_point_speed(truth)};
  const double dt = last_tick_ns_ == INT64_MIN ? 0.0 : static_cast<double>(truth.time_ns - last_tick_ns_) * 1e-9;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double v = spec_.is_signed ? speeds[i] : std::abs(speeds[i]);
    distance_m_[i] += (1.0 + spec_.scale_error) * 0.5 * (v + last_speed_mps_[i]) * dt;
    last_speed_mps_[i] = v;
  }
  last_tick_ns_ = truth.time_ns;
  gear_for(truth.speed_mps);
}

void WheelModel::fill_ticks(const TruthSample& truth, WheelTicks& out) const {
  out = WheelTicks{};
  out.header.time_ns = truth.time_ns;
  out.header.time_source = TimeSource::kGps;
  out.rollover = spec_.tick_rollover;
  out.gear = last_gear_;
  out.is_signed = spec_.is_signed;
}

namespace {
// The count of a rolled distance on a counter wrapping at `rollover` (0: 2^32).
std::uint32_t count_of(double distance_m, double m_per_tick, std::uint64_t rollover) {
  const std::int64_t n = static_cast<std::int64_t>(std::floor(distance_m / m_per_tick));
  const std::int64_t range = rollover == 0 ? (std::int64_t{1} << 32) : static_cast<std::int64_t>(rollover);
  return static_cast<std::uint32_t>(((n % range) + range) % range);
}
}  // namespace

void WheelModel::make_wheel_ticks(const TruthSample& truth, WheelTicks& out) const {
  fill_ticks(truth, out);
  out.channels = 4;
  out.header.valid = WheelTicks::kValidFrontLeft | WheelTicks::kValidFrontRight | WheelTicks::kValidRearLeft |
                     WheelTicks::kValidRearRight;
  for (std::size_t i = 0; i < 4; ++i) out.ticks[i] = count_of(distance_m_[i], spec_.m_per_tick, spec_.tick_rollover);
}

void WheelModel::make_vehicle_ticks(const TruthSample& truth, WheelTicks& out) const {
  fill_ticks(truth, out);
  out.channels = 1;
  out.header.valid = WheelTicks::kValidFrontLeft;
  out.ticks[0] = count_of(distance_m_[4], spec_.m_per_tick, spec_.tick_rollover);
}

}  // namespace navfuse::sim

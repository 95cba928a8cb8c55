#include "filter/measurements/wheel_ticks.hpp"

#include <cmath>

namespace navfuse::filter {

static_assert(WheelTicks::kValidFrontLeft == WheelSpeeds::kValidFrontLeft &&
                  WheelTicks::kValidFrontRight == WheelSpeeds::kValidFrontRight &&
                  WheelTicks::kValidRearLeft == WheelSpeeds::kValidRearLeft &&
                  WheelTicks::kValidRearRight == WheelSpeeds::kValidRearRight,
              "tick and speed validity bits name the same wheels");

std::int64_t tick_delta(std::uint32_t from, std::uint32_t to, std::uint64_t rollover, bool is_signed) {
  const std::uint64_t range = rollover == 0 ? (std::uint64_t{1} << 32) : rollover;
  const std::uint64_t up = ((static_cast<std::uint64_t>(to) % range) + range - static_cast<std::uint64_t>(from) % range) % range;
  if (is_signed && up >= (range + 1) / 2) return static_cast<std::int64_t>(up) - static_cast<std::int64_t>(range);
  return static_cast<std::int64_t>(up);
}

std::optional<TickSpeed> speed_from_ticks(const WheelTicks& previous, const WheelTicks& current,
                                          double m_per_tick, double speed_std_mps) {
  const double dt = static_cast<double>(current.header.time_ns - previous.header.time_ns) * 1e-9;
  if (!(dt > 0.0)) return std::nullopt;
  const double quantisation_mps = m_per_tick / dt / std::sqrt(6.0);
  const double std_mps = std::hypot(speed_std_mps, quantisation_mps);
  const std::uint32_t valid = previous.header.valid & current.header.valid;
  const auto speed_of = [&](std::size_t i) {
    return static_cast<double>(tick_delta(previous.ticks[i], current.ticks[i], current.rollover, current.is_signed)) *
           m_per_tick / dt;
  };
  std::optional<SpeedReading> reading;
  if (current.channels == 1) {
    VehicleSpeed v;
    v.header = current.header;
    v.header.valid = (valid & WheelTicks::kValidFrontLeft) != 0 ? VehicleSpeed::kValidSpeed : 0u;
    v.speed_mps = speed_of(0);
    v.gear = current.gear;
    v.is_signed = current.is_signed;
    v.speed_std_mps = std_mps;
    reading = speed_from_vehicle(v, std_mps);
  } else {
    // WheelTicks and WheelSpeeds share the wheel order and validity bits (FL, FR, RL, RR).
    WheelSpeeds w;
    w.header = current.header;
    w.header.valid = valid;
    for (std::size_t i = 0; i < 4; ++i) w.speed_mps[i] = speed_of(i);
    w.gear = current.gear;
    w.is_signed = current.is_signed;
    w.speed_std_mps = std_mps;
    reading = speed_from_wheels(w, std_mps);
  }
  if (!reading) return std::nullopt;
  return TickSpeed{*reading, dt};
}

Observation wheel_tick_observation(const StateView& s, const TickSpeed& speed, const Eigen::Vector3d& lever_arm_m,
                                   double point_accel_mps2) {
  Observation obs = wheel_speed_observation(s, speed.reading, lever_arm_m, point_accel_mps2);
  const double back_mps = 0.5 * point_accel_mps2 * speed.interval_s;
  obs.residual(0) -= (1.0 + s.x.wheel_scale) * back_mps;
  obs.h(0, sx::kWheelScale) -= back_mps;
  return obs;
}

}  // namespace navfuse::filter

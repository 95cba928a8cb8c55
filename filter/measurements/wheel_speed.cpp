#include "filter/measurements/wheel_speed.hpp"

namespace navfuse::filter {
namespace {

double apply_direction(double speed, bool is_signed, Gear gear) {
  if (is_signed) return speed;
  return gear == Gear::kReverse ? -std::abs(speed) : std::abs(speed);
}

}  // namespace

std::optional<SpeedReading> speed_from_wheels(const WheelSpeeds& m, double default_std) {
  const double std_mps = m.speed_std_mps > 0.0 ? m.speed_std_mps : default_std;
  const auto pair = [&](std::uint32_t a, std::uint32_t b, int ia, int ib) -> std::optional<double> {
    if ((m.header.valid & a) == 0 || (m.header.valid & b) == 0) return std::nullopt;
    return 0.5 * (m.speed_mps[static_cast<std::size_t>(ia)] + m.speed_mps[static_cast<std::size_t>(ib)]);
  };
  // Averaging two independent wheels halves the variance.
  if (auto rear = pair(WheelSpeeds::kValidRearLeft, WheelSpeeds::kValidRearRight, 2, 3)) {
    return SpeedReading{apply_direction(*rear, m.is_signed, m.gear), std_mps / std::sqrt(2.0)};
  }
  if (auto front = pair(WheelSpeeds::kValidFrontLeft, WheelSpeeds::kValidFrontRight, 0, 1)) {
    return SpeedReading{apply_direction(*front, m.is_signed, m.gear), 2.0 * std_mps};
  }
  return std::nullopt;
}

std::optional<SpeedReading> speed_from_vehicle(const VehicleSpeed& m, double default_std) {
  if ((m.header.valid & VehicleSpeed::kValidSpeed) == 0) return std::nullopt;
  return SpeedReading{apply_direction(m.speed_mps, m.is_signed, m.gear),
                      m.speed_std_mps > 0.0 ? m.speed_std_mps : default_std};
}

double forward_accel_mps2(const StateView& s, const Eigen::Vector3d& force_b_mps2) {
  const Eigen::Matrix3d c_bn = s.c_nb.transpose();
  const Eigen::Vector3d v_b = c_bn * s.x.vel_ned_mps;
  return force_b_mps2.x() + (c_bn * s.earth.gravity_ned_mps2).x() - s.rate_b_rps.cross(v_b).x();
}

Observation wheel_speed_observation(const StateView& s, const SpeedReading& reading,
                                    const Eigen::Vector3d& lever_arm_m, double point_accel_mps2) {
  const BodyVelocityModel v = body_velocity_at(s, lever_arm_m, true);
  const double scale = 1.0 + s.x.wheel_scale;
  const double forward_mps = v.vel_mps.x() + point_accel_mps2 * s.shift_s;
  Observation obs(1);
  obs.residual(0) = scale * forward_mps - reading.speed_mps;
  obs.h.row(0) = scale * v.jacobian.row(0);
  obs.h(0, sx::kWheelScale) = forward_mps;
  obs.r(0, 0) = reading.std_mps * reading.std_mps;
  return obs;
}

}  // namespace navfuse::filter

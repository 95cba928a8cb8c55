// Vehicle vibration on the IMU output (see vibration_model.hpp for the model and its sources).
#include "apps/sim/vibration_model.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"

namespace navfuse::sim {

VibrationSpec car_vibration() {
  VibrationSpec v;
  v.accel_rms_idle_mps2 = 0.1;
  v.accel_rms_per_mps = 0.01;   // 0.3 m/s^2 at 20 m/s
  v.gyro_rms_idle_dps = 0.1;
  v.gyro_rms_per_mps = 0.02;    // 0.5 deg/s at 20 m/s
  v.engine_idle_hz = 26.7;      // 800 rpm, 2nd order of a four-cylinder engine
  v.engine_hz_per_mps = 2.0;    // ~2000 rpm at 20 m/s
  v.engine_accel_amplitude_mps2 = 0.5;
  v.engine_gyro_amplitude_dps = 0.2;
  return v;
}

VibrationModel::VibrationModel(const VibrationSpec& spec, std::uint64_t seed)
    : spec_(spec), rng_(seed, RandomStream::kVibration) {
  for (int i = 0; i < 3; ++i) axis_phase_rad_[i] = 2.0 * rot::kPi * rng_.uniform();
  engine_phase_rad_ = 2.0 * rot::kPi * rng_.uniform();
}

void VibrationModel::apply(bool increments, double dt_s, double speed_mps, Eigen::Vector3d& gyro,
                           Eigen::Vector3d& accel) {
  if (!spec_.enabled()) return;
  const double speed = std::abs(speed_mps);
  const double accel_rms = spec_.accel_rms_idle_mps2 + spec_.accel_rms_per_mps * speed;
  const double gyro_rms =
      (spec_.gyro_rms_idle_dps + spec_.gyro_rms_per_mps * speed) * rot::kDegToRad;
  // Broadband: the mean over dt has std `rms`, so an increment has std rms * dt.
  const double to_output = increments ? dt_s : 1.0;
  const Eigen::Vector3d wg(rng_.normal(), rng_.normal(), rng_.normal());
  const Eigen::Vector3d wa(rng_.normal(), rng_.normal(), rng_.normal());
  gyro += gyro_rms * to_output * wg;
  accel += accel_rms * to_output * wa;

  // Engine tone, frequency held over the interval (it changes on the scale of seconds).
  const double omega = 2.0 * rot::kPi * (spec_.engine_idle_hz + spec_.engine_hz_per_mps * speed);
  const double phase0 = engine_phase_rad_;
  const double phase1 = phase0 + omega * dt_s;
  engine_phase_rad_ = std::fmod(phase1, 2.0 * rot::kPi);
  Eigen::Vector3d tone;
  for (int i = 0; i < 3; ++i) {
    const double a = phase0 + axis_phase_rad_[i], b = phase1 + axis_phase_rad_[i];
    tone[i] = increments ? (std::cos(a) - std::cos(b)) / omega : std::sin(b);
  }
  gyro += spec_.engine_gyro_amplitude_dps * rot::kDegToRad * tone;
  accel += spec_.engine_accel_amplitude_mps2 * tone;
}

}  // namespace navfuse::sim

// Vehicle vibration seen by a strapdown IMU: the engine and the road shake the sensor far beyond
// the noise its data sheet quotes for a sensor at rest. Two parts, per sensor axis:
//
//  - Broadband: white at the output rate, with an RMS that grows with speed (road excitation).
//    A MEMS IMU samples internally at a few kHz and decimates to its output rate; vibration
//    above its internal Nyquist frequency folds into the passband (aliasing) and, summed into
//    the increments, is indistinguishable from extra white rate noise: an excess angle / velocity
//    random walk of N = rms * sqrt(dt) per sqrt(s) (IEEE Std 952 C.1 relation between a rate
//    sample's std over dt and the random-walk coefficient).
//  - Engine tone: a sinusoid at the firing frequency, which follows engine speed (for a
//    four-stroke four-cylinder engine the 2nd engine order, 2 * rpm / 60: ~27 Hz at 800 rpm idle,
//    ~67 Hz at 2000 rpm). Increments integrate it exactly, (A / w)(cos(phi0) - cos(phi1)), so it
//    mostly cancels over successive samples; rate outputs sample it at the stamp, where a tone
//    above half the output rate aliases to a lower frequency.
//
// The vibration is a small oscillation of the sensor about its mount (millimetres): it does not
// move the truth trajectory, only the sensor output. Levels: ISO 2631-1:1997 Annex C rates
// whole-body vibration in vehicles below 0.315 m/s^2 RMS as "not uncomfortable" and
// 0.315-0.63 m/s^2 as "a little uncomfortable"; car_vibration() stays at or below the first
// band (0.1 m/s^2 at idle rising to 0.3 m/s^2 at 20 m/s), where a car on an ordinary road is
// meant to be. That is 14-42 times the industrial grade's VRW of 0.03 m/s/sqrt(h) at 200 Hz
// (0.0071 m/s^2 per sample), the order of the 10-40x noise inflation a public filter needed on
// a real roof-mounted drive (issue 14).
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "apps/sim/random.hpp"

namespace navfuse::sim {

struct VibrationSpec {
  // Broadband RMS per axis at the output rate: idle + per_mps * |speed|.
  double accel_rms_idle_mps2 = 0.0;
  double accel_rms_per_mps = 0.0;  // (m/s^2) per (m/s)
  double gyro_rms_idle_dps = 0.0;
  double gyro_rms_per_mps = 0.0;   // (deg/s) per (m/s)
  // Engine tone: frequency idle_hz + hz_per_mps * |speed|, amplitude per axis (0: off).
  double engine_idle_hz = 26.7;
  double engine_hz_per_mps = 2.0;
  double engine_accel_amplitude_mps2 = 0.0;
  double engine_gyro_amplitude_dps = 0.0;

  bool enabled() const {
    return accel_rms_idle_mps2 > 0.0 || accel_rms_per_mps > 0.0 || gyro_rms_idle_dps > 0.0 ||
           gyro_rms_per_mps > 0.0 || engine_accel_amplitude_mps2 > 0.0 ||
           engine_gyro_amplitude_dps > 0.0;
  }
};

// A passenger car on ordinary roads, sensor on a rigid roof mount (levels: file comment).
VibrationSpec car_vibration();

// Stateful vibration generator, deterministic for a seed, with its own random stream so that
// switching vibration on does not change the IMU's other errors.
class VibrationModel {
 public:
  VibrationModel(const VibrationSpec& spec, std::uint64_t seed);

  // Adds the vibration over one output interval of `dt_s` ending now, at vehicle speed
  // `speed_mps`, to sensor-frame increments (increments = true) or rates.
  void apply(bool increments, double dt_s, double speed_mps, Eigen::Vector3d& gyro,
             Eigen::Vector3d& accel);

 private:
  VibrationSpec spec_;
  Rng rng_;
  double engine_phase_rad_ = 0.0;
  Eigen::Vector3d axis_phase_rad_ = Eigen::Vector3d::Zero();  // per-axis phase of the tone
};

}  // namespace navfuse::sim

// The white noise an IMU's samples carry, measured from the samples themselves.
//
// A data sheet's angle and velocity random walk describe the sensor at rest on a bench. Bolted to
// a car, the engine and the road add broadband vibration that the sensor's internal decimation
// folds into its output band (apps/sim/vibration_model.hpp): white at the output rate and 10-60
// times the data sheet's level in std. Preintegration weighted with the data sheet then trusts
// the IMU's integration beyond what it holds, and the installation estimates (the time offset
// against the lever arm's x above all) follow the vibration. The IMU factors' own residuals do not
// show it: the free epoch states take up most of their redundancy (calibration_problem.cpp).
//
// What shows it is the samples' high-frequency scatter. For a rate signal x_k = s_k + e_k with
// white e_k of std sigma, the second difference d_k = x_{k+1} - 2 x_k + x_{k-1} has variance
// 6 sigma^2 plus that of the true signal's second difference, which for a vehicle (jerk times
// dt^2) is orders below a MEMS sensor's noise at 100-200 Hz. The median of d^2 over a window (a
// bump or a quantisation step does not move it) is 0.4549 * 6 sigma^2 for normal e (the median
// of chi-square with one degree of freedom). The random-walk density is then sigma * sqrt(dt)
// (IEEE Std 952-1997 annex C: a white rate's per-sample std over dt against its random walk).
// An engine tone sampled at the output rate counts too: for the fit it is noise as well.
#pragma once

#include <cstddef>
#include <vector>

#include "core/measurements/measurements.hpp"

namespace navfuse::calib {

struct ImuWhiteNoise {
  double gyro_rad_rts = 0.0;   // angle random walk, rad/sqrt(s)
  double accel_mps_rts = 0.0;  // velocity random walk, (m/s)/sqrt(s)
  std::size_t samples = 0;     // second differences pooled per axis (0: too few samples)
};

// Over imu[first..last] (inclusive), the three axes pooled per sensor. Fewer than
// kMinWhiteNoiseSamples second differences give samples = 0 and zero densities.
// `block_s` sums the increments over blocks that long before differencing (0: single samples).
ImuWhiteNoise measure_white_noise(const std::vector<ImuSample>& imu, std::size_t first, std::size_t last,
                                  double block_s = 0.0);

inline constexpr std::size_t kMinWhiteNoiseSamples = 16;

// Per sensor, the smaller of two measurements (one that measured nothing is ignored): white noise
// shows the same at every block length, the other things a sensor's output carries do not.
ImuWhiteNoise least_white_noise(const ImuWhiteNoise& a, const ImuWhiteNoise& b);

}  // namespace navfuse::calib

// Odometry from tick counters (wheel encoders, a vehicle odometer's pulses): the count change
// between two samples times the tick-to-metre scale is the distance the measurement point
// travelled (Groves 2nd ed. §6.3.1, odometers count wheel-rotation pulses), and that over the
// interval is the mean forward speed. The count's time is the newer sample's, so the model
// takes the mean of a speed changing at the forward acceleration a over the interval T, the speed
// at its midpoint: s_mean = (1 + k) (e_x^T v_wheel + a (shift - T / 2)), the wheel_speed.hpp model
// shifted back by T / 2 from the count's time.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "core/measurements/measurements.hpp"
#include "filter/measurements/state_view.hpp"
#include "filter/measurements/wheel_speed.hpp"

namespace navfuse::filter {

// Count change from `from` to `to` of a counter that wraps at `rollover` (0: 2^32). An unsigned
// counter only grows, so the change is taken modulo the rollover in [0, rollover); a signed one
// (counts that decrease when driving backward) in [-rollover / 2, rollover / 2).
std::int64_t tick_delta(std::uint32_t from, std::uint32_t to, std::uint64_t rollover, bool is_signed);

// The mean speed over the interval between two samples of one counter set, and the interval.
struct TickSpeed {
  SpeedReading reading;
  double interval_s = 0.0;
};

// The counts of `previous` and `current` (same stream, current later) as a speed: four wheels
// through speed_from_wheels (the rear pair, else the front), one channel as the vehicle speed.
// The std adds the count quantisation to `speed_std_mps`: each reading is up to one tick short of
// the true count, uniformly, so their difference has a variance of 1/6 tick^2.
// nullopt when the interval is not positive or no channel (pair) is valid in both samples.
std::optional<TickSpeed> speed_from_ticks(const WheelTicks& previous, const WheelTicks& current,
                                          double m_per_tick, double speed_std_mps);

// The mean-speed observation above, at the view's time shift (wheel_speed.hpp): the speed model
// moved back by T / 2 - shift. `point_accel_mps2` (a, forward_accel_mps2() of the newest
// compensated specific force) is a constant of the update: its error, times T / 2 - shift, is far
// below the count quantisation.
Observation wheel_tick_observation(const StateView& s, const TickSpeed& speed, const Eigen::Vector3d& lever_arm_m,
                                   double point_accel_mps2);

}  // namespace navfuse::filter

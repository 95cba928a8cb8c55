// Simulated wheel odometry: a vehicle speed (VehicleSpeed) at a chosen point, and/or four wheel
// speeds (WheelSpeeds), with a scale error and white noise.
//
// Speed of a point P at lever arm l (vehicle frame) relative to the earth, in the vehicle frame:
//   v_P = v_b + omega_eb_b x l,  v_b = C_bn v_n,  omega_eb_b = omega_ib_b - C_bn omega_ie_n
// (the rigid-body lever-arm relation, as for odometry in Groves §6.3). VehicleSpeed reports the
// body-x component of v_P at `lever_arm_m` (e.g. the rear axle centre). WheelSpeeds reports, for each wheel contact point,
// the horizontal speed magnitude (steered front wheels roll along their own velocity) with the
// sign of its body-x component: rear wheels at lever_arm_m +- track/2 laterally, front wheels
// `wheelbase_m` further forward.
// Measured = (1 + scale_error) * true + noise. At exactly zero true speed the output is exactly
// zero, like an encoder that sees no pulses.
#pragma once

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "apps/sim/random.hpp"
#include "apps/sim/trajectory.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::sim {

struct WheelSpec {
  bool vehicle_speed = false;  // output VehicleSpeed
  bool wheel_speeds = false;   // output WheelSpeeds (all four wheels)
  double rate_hz = 50.0;       // on the GPS-time grid of 1/rate (whole ns)
  Eigen::Vector3d lever_arm_m = Eigen::Vector3d::Zero();  // speed measurement point
  double track_m = 1.6;       // distance between left and right wheels
  double wheelbase_m = 2.8;   // distance from the rear to the front axle
  double scale_error = 0.0;   // fractional: 0.01 = reads 1 % high
  double noise_std_mps = 0.05;
  double reported_std_mps = 0.0;  // speed_std_mps field; 0 = report noise_std_mps
  bool is_signed = true;          // false: magnitudes only, direction from gear
  double latency_s = 0.0;         // delivery delay (stamp stays the measurement time)
  // Tick counters: the distance each point rolled, (1 + scale_error) times the true distance
  // (trapezoidal over the wheel epochs), in whole counts of m_per_tick, wrapping at
  // tick_rollover (0: 2^32). Unsigned counters count the distance either way (direction from
  // gear); signed ones count down when reversing.
  bool wheel_ticks = false;    // output WheelTicks, four wheels (FusionEngine WheelTickInput)
  bool vehicle_ticks = false;  // output WheelTicks, one channel at lever_arm_m (VehicleTickInput)
  double m_per_tick = 0.02;
  std::uint64_t tick_rollover = 0;
};

class WheelModel {
 public:
  WheelModel(const WheelSpec& spec, std::uint64_t seed);

  const WheelSpec& spec() const { return spec_; }
  std::int64_t period_ns() const { return period_ns_; }
  std::int64_t latency_ns() const { return latency_ns_; }
  bool enabled() const {
    return spec_.vehicle_speed || spec_.wheel_speeds || spec_.wheel_ticks || spec_.vehicle_ticks;
  }

  void make_vehicle_speed(const TruthSample& truth, VehicleSpeed& out);
  void make_wheel_speeds(const TruthSample& truth, WheelSpeeds& out);
  // Advance the tick distances to `truth` (call once per wheel epoch, before the make_*_ticks).
  void advance_ticks(const TruthSample& truth);
  void make_wheel_ticks(const TruthSample& truth, WheelTicks& out) const;
  void make_vehicle_ticks(const TruthSample& truth, WheelTicks& out) const;

 private:
  // True signed speeds of the wheel contact points FL, FR, RL, RR and of the lever-arm point.
  std::array<double, 4> true_wheel_speeds(const TruthSample& truth) const;
  double true_point_speed(const TruthSample& truth) const;
  void fill_ticks(const TruthSample& truth, WheelTicks& out) const;

  Gear gear_for(double speed_mps);
  double measure(double true_speed_mps);

  WheelSpec spec_;
  std::int64_t period_ns_ = 0;
  std::int64_t latency_ns_ = 0;
  Rng rng_;
  Gear last_gear_ = Gear::kForward;
  // Rolled distance of FL, FR, RL, RR and of the lever-arm point, and their last speeds.
  std::array<double, 5> distance_m_{};
  std::array<double, 5> last_speed_mps_{};
  std::int64_t last_tick_ns_ = INT64_MIN;
};

// True speed of the point at `lever_arm_m` along body x, and its velocity in the vehicle frame.
Eigen::Vector3d point_velocity_vehicle(const TruthSample& truth, const Eigen::Vector3d& lever_arm_m);

}  // namespace navfuse::sim

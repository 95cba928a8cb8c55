// Simulated GNSS receiver: position and velocity of the antenna at a fixed rate, with noise that
// depends on the fix type, outages, delivery latency, glitches (outliers and permanent jumps) and
// an optional dual-antenna heading.
//
// Noise model, per NED axis (horizontal sigma applies to north and east each):
//   e = e_white + e_gm,  e_white ~ N(0, (1 - c) sigma^2),
//   e_gm first-order Gauss-Markov with stationary variance c sigma^2 and correlation time tau
//   (the slowly varying part of the ranging errors: ionosphere, troposphere, orbit/clock,
//   multipath), discretised exactly like the IMU bias in imu_error_model.hpp.
// The reported covariance is diag(sigma_h^2, sigma_h^2, sigma_v^2): the total stationary variance
// of the generated error, so a filter's NEES on GNSS residuals is consistent (the correlated part
// is of course not white; set c = 0 for a white-noise consistency test).
// Glitches and jumps are NOT in the reported covariance: they are the outliers a filter must
// reject.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "apps/sim/gnss_multipath.hpp"
#include "apps/sim/random.hpp"
#include "apps/sim/time_interval.hpp"
#include "apps/sim/trajectory.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::sim {

struct GnssNoise {
  double horizontal_std_m = 1.5;   // per axis (north, east), 1 sigma
  double vertical_std_m = 3.0;
  double correlated_fraction = 0.0;  // share c of the variance that is time-correlated, [0, 1]
  double correlation_time_s = 60.0;
  double horizontal_velocity_std_mps = 0.05;  // per axis, white
  double vertical_velocity_std_mps = 0.1;
  std::uint8_t num_sats = 10;  // reported satellite count
};
// Typical figures per fix type: standalone (kFix3D) 1.5 m / 3 m, DGNSS/SBAS 0.5 m / 1 m,
// RTK float 0.3 m / 0.5 m, RTK fixed 0.02 m / 0.03 m, PPP 0.1 m / 0.2 m.
GnssNoise default_gnss_noise(GnssFixType fix);
// The same reported std devs with the error correlation a real receiver's solution has per fix
// type, for drives whose fix type changes: RTK fixed white (carrier-phase noise, centimetres);
// RTK float 90 % of the variance correlated over 60 s (the float ambiguities converge slowly, so
// the float error is a slowly wandering bias; fixing snaps it to the truth: the step a filter must
// absorb at a float-to-fixed transition); DGNSS/SBAS and standalone 80 % correlated over 60 s /
// 120 s (residual ionosphere, troposphere, orbit and clock errors; Groves §9.3). One correlated
// state per receiver scaled by the fix type's sigma, so the error is continuous within a fix type
// and steps when the type (and its sigma) changes.
GnssNoise receiver_fix_noise(GnssFixType fix);

// A different fix type (and its noise) over an interval, e.g. RTK dropping to float.
struct GnssFixInterval {
  TimeInterval interval;
  GnssFixType fix = GnssFixType::kRtkFloat;
  GnssNoise noise = default_gnss_noise(GnssFixType::kRtkFloat);
};

// From `time_s` on, every reported position is offset by `offset_ned_m` (a wrong ambiguity fix,
// a datum change): a permanent jump.
struct GnssJump {
  double time_s = 0.0;
  Eigen::Vector3d offset_ned_m = Eigen::Vector3d::Zero();
};

struct GnssSpec {
  bool enabled = true;
  std::uint8_t receiver_id = 0;  // stamped on the fixes (0 primary receiver, 1 the second one)
  double rate_hz = 5.0;  // fixes on the GPS-time grid of 1/rate (whole ns)
  GnssFixType fix = GnssFixType::kFix3D;
  GnssNoise noise = default_gnss_noise(GnssFixType::kFix3D);
  std::vector<GnssFixInterval> fix_schedule;  // overrides fix/noise inside each interval
  bool velocity = true;                       // also output GnssVelocity
  Eigen::Vector3d lever_arm_m = Eigen::Vector3d::Zero();  // primary antenna, vehicle frame
  std::vector<TimeInterval> outages;  // no position, velocity or heading inside
  double latency_s = 0.0;  // delivery delay: header.time_ns stays the measurement time

  // Outliers: each fix is displaced, independently with this probability, by `glitch_offset_m`
  // horizontally in a uniformly random direction (covariance unchanged).
  double glitch_fraction = 0.0;
  double glitch_offset_m = 50.0;
  std::vector<GnssJump> jumps;
  // Short-lived multipath offsets, covariance unchanged (gnss_multipath.hpp).
  MultipathSpec multipath{};

  // Dual-antenna heading (GnssHeading): azimuth/elevation of the baseline from the primary to the
  // secondary antenna, with white noise of the given std (reported as such).
  bool heading = false;
  Eigen::Vector3d secondary_lever_arm_m = Eigen::Vector3d::Zero();
  double heading_std_rad = 0.2 * 3.14159265358979323846 / 180.0;
  double heading_pitch_std_rad = 0.4 * 3.14159265358979323846 / 180.0;
};

// Factories for the two reference modes of the filter tests.
GnssSpec gnss_standalone(double rate_hz = 5.0);  // kFix3D, 1.5 m / 3 m
GnssSpec gnss_rtk_fixed(double rate_hz = 10.0);  // kRtkFixed, 0.02 m / 0.03 m

// Stateful generator, deterministic for a seed.
class GnssModel {
 public:
  GnssModel(const GnssSpec& spec, std::uint64_t seed);

  const GnssSpec& spec() const { return spec_; }
  std::int64_t period_ns() const { return period_ns_; }
  std::int64_t latency_ns() const { return latency_ns_; }
  // Whether a fix is produced at `t_s` (seconds since scenario start): enabled, not in an outage.
  bool available(double t_s) const;
  // Fix type and noise in force at `t_s`.
  const GnssNoise& noise_at(double t_s, GnssFixType* fix) const;

  // Generates the epoch at `truth.time_ns` (t_s since the start). Fills the outputs and returns
  // which were produced (none inside an outage).
  struct Epoch {
    bool has_position = false, has_velocity = false, has_heading = false;
    bool glitched = false;  // this fix carries a glitch displacement
    bool multipath = false;  // this fix carries a multipath offset
  };
  Epoch make_epoch(const TruthSample& truth, double t_s, GnssPosition& pos, GnssVelocity& vel,
                   GnssHeading& heading);

 private:
  GnssSpec spec_;
  std::int64_t period_ns_ = 0;
  std::int64_t latency_ns_ = 0;
  Rng rng_;
  Rng heading_rng_;
  std::vector<MultipathEvent> multipath_;
  Eigen::Vector3d gm_unit_ = Eigen::Vector3d::Zero();  // correlated error / its sigma, per axis
  std::int64_t last_epoch_ns_ = 0;
  bool have_last_epoch_ = false;
};

// Position of a point at `lever_arm_m` (vehicle frame) from the reference point of `truth`, and
// its velocity in NED (rigid-body lever-arm relation v_n + C_nb (omega_eb_b x l), with
// omega_eb_b = omega_ib_b - C_bn omega_ie_n; Groves §14.3 loosely-coupled measurement model).
geo::Llh lever_arm_position(const TruthSample& truth, const Eigen::Vector3d& lever_arm_m);
Eigen::Vector3d lever_arm_velocity_ned(const TruthSample& truth, const Eigen::Vector3d& lever_arm_m);

}  // namespace navfuse::sim

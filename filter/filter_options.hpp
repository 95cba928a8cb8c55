// Everything that tunes the filter, in SI units, with documented defaults. `options_from_config`
// fills the IMU noise, lever arms, mounting and wheel noise from the YAML configuration
// (DESIGN.md keys); the rest keeps the defaults below unless the caller changes it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "core/config/config.hpp"
#include "core/measurements/measurements.hpp"
#include "filter/state_layout.hpp"

namespace navfuse::filter {

// Stochastic IMU model (IEEE Std 952 terms), SI. Biases are first-order Gauss-Markov processes
// with the given stationary std and correlation time, plus the turn-on uncertainty as the initial
// covariance.
struct ImuNoise {
  double gyro_arw_rad_rts = 0.08 * 3.14159265358979323846 / 180.0 / 60.0;  // rad/sqrt(s)
  double gyro_bias_std_rps = 1.5 * 3.14159265358979323846 / 180.0 / 3600.0;
  double gyro_bias_corr_time_s = 300.0;
  double accel_vrw_mps_rts = 0.02 / 60.0;  // m/s/sqrt(s)
  double accel_bias_std_mps2 = 2.0e-5;
  double accel_bias_corr_time_s = 300.0;
  double initial_gyro_bias_std_rps = 20.0 * 3.14159265358979323846 / 180.0 / 3600.0;
  double initial_accel_bias_std_mps2 = 0.01;
  double initial_gyro_scale_std = 1000e-6;  // used only with StateSelection::gyro_scale
  double initial_accel_scale_std = 1000e-6;
};

// Innovation-based adaptation (control/innovation_adaptation.hpp): how the filter notices and
// repairs an overconfident covariance.
struct AdaptationOptions {
  bool enabled = true;
  double window_s = 1.0;        // innovations looked at: "persistently" means within this
  int min_samples = 3;          // and at least this many of them
  double inflate_ratio = 3.0;   // median NIS per dimension that re-inflates P (errors 1.7x spread)
  double max_inflation = 1e4;   // largest single scaling of the P block (std x 100)
  double max_process_noise_scale = 100.0;  // random walks at most 10x the data sheet's std
  // Largest multiplier on an aid's reported variances (measurement_noise_adaptation.hpp):
  // std devs at most 10x what the receiver claims.
  double max_measurement_noise_scale = 100.0;
  double process_noise_gain = 0.25;        // exponent per sample of the scale's adaptation
};

// Magnetometer heading aiding (control/magnetometer_control.hpp). Off by default: a magnetometer
// near steel, motors or cables is wrong by tens of degrees, which only the installer can judge.
struct MagnetometerOptions {
  bool enabled = false;
  double heading_std_rad = 5.0 * 3.14159265358979323846 / 180.0;
  std::optional<double> declination_rad;  // nullopt: GeographicLib's magnetic model, if installed
  Eigen::Vector3d hard_iron_gauss = Eigen::Vector3d::Zero();  // sensor frame, subtracted
  // The earth's total field is 0.22-0.67 gauss everywhere (WMM2020 report, fig. 11); a reading
  // outside [min, max] is disturbed (a car alongside, a motor starting) and is not fused.
  double min_field_gauss = 0.15;
  double max_field_gauss = 0.8;
  // Below this horizontal component (near the magnetic poles, or a badly tilted sensor) the
  // heading is too noisy to use.
  double min_horizontal_field_gauss = 0.05;
};

// Barometric height aiding (control/baro_control.hpp): relative height, anchored to the
// filter's height at the first fused sample. Off by default.
struct BaroOptions {
  bool enabled = false;
  double height_std_m = 1.0;
};

// Accelerometer tilt aiding (control/tilt_control.hpp): gravity as the roll/pitch reference while
// nothing observes velocity.
struct AccelTiltOptions {
  bool enabled = false;  // config: on for pedestrian and marine platforms
  double std_mps2 = 0.5;            // the vehicle's own acceleration, as noise
  double max_deviation_mps2 = 1.0;  // | |f| - g | beyond this: manoeuvring, not used
  double window_s = 0.1;            // specific force averaged over this, one update per window
};

// Aiding sources that may carry a chi-square gate of their own (config gates.<source>, bound in
// filter_options.cpp); unset, a source is gated by its update's dimension.
enum class GatedAid : std::uint8_t {
  kGnssPosition,
  kGnssVelocity,
  kGnssHeading,
  kOdometry,          // wheel speed, vehicle speed, wheel ticks
  kNhc,               // non-holonomic constraint
  kStationary,        // zero-velocity and zero-rate updates
  kGravity,           // accelerometer tilt reference
  kPressure,          // barometric height
  kMagnetometer,
  kExternalPosition,
  kExternalVelocity,
  kExternalHeading,
  kCount,
};

// Where a car does not slip when its config does not say (no nhc.lever_arm_m, no wheel lever arm):
// the constraint then holds at the IMU, and this is how far off that guess may be, 1 sigma per
// vehicle axis. An IMU on a car sits between the axles or over the rear one, 0-3 m ahead of the
// rear-axle centre (x: 1.5 +- 1.5 m), near the centreline and up to a metre above the axle.
inline const Eigen::Vector3d kUnknownNonSlipPointStdM{1.5, 0.5, 0.5};

struct FilterOptions {
  ImuNoise imu;
  MagnetometerOptions magnetometer;
  BaroOptions baro;
  AccelTiltOptions accel_tilt;
  AdaptationOptions adaptation;
  StateSelection states;

  // Geometry (vehicle frame FRD, metres; mounting sensor -> vehicle roll, pitch, yaw, 3-2-1, rad).
  Eigen::Vector3d mounting_rpy_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d gnss_lever_arm_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d gnss_secondary_lever_arm_m = Eigen::Vector3d::Zero();  // zero: heading = yaw
  Eigen::Vector3d wheel_lever_arm_m = Eigen::Vector3d::Zero();

  // Odometry and land-vehicle constraints.
  double wheel_speed_std_mps = 0.05;  // used when a measurement reports 0
  double wheel_m_per_tick = 0.0;      // tick-to-metre scale of tick counters; 0: ticks not fused
  double initial_wheel_scale_std = 0.02;
  bool land_vehicle = true;  // apply the non-holonomic constraint (nhc.enabled; default: platform land)
  // The point that does not slip sideways or leave the road (the rear-axle centre of a car);
  // nullopt: the wheel lever arm, which is where odometers usually measure.
  std::optional<Eigen::Vector3d> nhc_lever_arm_m;
  // Where the constraint is applied: nhc_lever_arm_m, else the wheel lever arm.
  Eigen::Vector3d nhc_point_m() const { return nhc_lever_arm_m.value_or(wheel_lever_arm_m); }
  // How well that point is known, 1 sigma per vehicle axis: its uncertainty enters the constraint's
  // noise through the rotation (nonholonomic.hpp). Zero: known.
  Eigen::Vector3d nhc_lever_arm_std_m = Eigen::Vector3d::Zero();
  double nhc_lateral_std_mps = 0.1;   // body y velocity at the wheel point
  double nhc_vertical_std_mps = 0.1;  // body z velocity at the wheel point
  double nhc_interval_s = 0.1;
  double nhc_min_speed_mps = 1.0;     // below this ZUPT/odometry take over
  double initial_mount_std_rad = 1.0 * 3.14159265358979323846 / 180.0;
  double initial_lever_arm_std_m = 0.1;
  double initial_gnss_time_offset_std_s = 0.05;  // used only with StateSelection::gnss_time_offset

  // Stationary detection and zero-velocity / zero-angular-rate updates.
  double stationary_window_s = 0.2;
  double stationary_gyro_rps = 0.01;        // mean |rate| over a window below this ...
  double stationary_accel_std_mps2 = 0.05;  // ... and specific-force scatter below this
  double stationary_max_speed_mps = 0.3;    // and odometry / GNSS / filter speed below this
  double zupt_std_mps = 0.02;
  // Apply zero-velocity and zero-rate updates at detected stops (platform: land, pedestrian).
  // Off, stops are still detected (they keep kinematic alignment and NHC away from rest).
  bool zero_velocity_updates = true;

  // Initialisation and heading alignment (MIP §6.4).
  double level_time_s = 1.0;             // stationary time averaged for levelling
  double level_timeout_s = 10.0;         // level from whatever was seen if never stationary
  std::optional<double> initial_heading_rad;  // configured heading source
  double initial_heading_std_rad = 5.0 * 3.14159265358979323846 / 180.0;  // its 1 sigma
  // Configured priors once levelled; unset, alignment.cpp derives them from how it levelled.
  std::optional<double> initial_tilt_std_rad;
  std::optional<double> initial_velocity_std_mps;
  double kinematic_alignment_speed_mps = 2.0;
  // The course is taken as the heading only when its own noise, velocity std over speed, is
  // below this: a fast speed from a noisy velocity gives no better course than a slow one.
  double kinematic_max_course_std_rad = 5.0 * 3.14159265358979323846 / 180.0;
  double kinematic_heading_std_rad = 2.0 * 3.14159265358979323846 / 180.0;
  // Heading from the course assumes motion along the vehicle's x axis: only a land vehicle
  // (platform: land) may use it. Velocity matching (velocity_matching_alignment.hpp) needs no
  // such assumption and is always on.
  bool course_alignment = true;
  double velocity_match_window_s = 6.0;  // longer spans accumulate tilt and bias errors
  int velocity_match_min_samples = 4;
  double velocity_match_max_std_rad = 5.0 * 3.14159265358979323846 / 180.0;
  // Added to the fit's own std for what it cannot see (tilt error, lever-arm motion).
  double velocity_match_allowance_rad = 1.0 * 3.14159265358979323846 / 180.0;

  // GNSS control.
  double gnss_timeout_s = 2.0;   // no position aiding for longer: dead reckoning
  double gnss_recovery_s = 3.0;  // sustained rejection for longer: re-anchor to GNSS
  // Steps between consecutive fixes (control/gnss_jump_check.hpp): the chi-square test of a step
  // against the inertial track, and how long the fixes after one are held out at most (0: off).
  double gnss_jump_gate = 30.0;
  double gnss_jump_hold_s = 10.0;
  // Smaller steps are not held out: following one costs no more than its size, and a turn of a
  // vibrating car with positions-only fixes makes 5 cm steps now and then (parking_drive). A
  // wrong RTK ambiguity moves the fix by about a carrier wavelength (19 cm at L1), multipath by
  // decimetres to metres.
  double gnss_jump_min_m = 0.1;
  // Jump-free position output (output_blend.hpp): a correction of at least `_min_m` reaches the
  // output over this time constant (0: the output jumps with the filter).
  double output_jump_blend_s = 0.25;
  double output_jump_blend_min_m = 0.1;
  // Chi-square innovation gate per measurement dimension (1, 2, 3): the 99.99 % quantiles.
  std::array<double, 3> chi2_gate = {15.14, 18.42, 21.11};
  // A gate of its own per aiding source (config gates.<aid>), applied to every update of that
  // source whatever its rows; 0: the by-dimension gate above.
  std::array<double, static_cast<std::size_t>(GatedAid::kCount)> aid_chi2_gate{};
  double gate_for(GatedAid aid, int rows) const {
    const double own = aid_chi2_gate[static_cast<std::size_t>(aid)];
    if (own > 0.0) return own;
    return rows >= 1 && rows <= 3 ? chi2_gate[static_cast<std::size_t>(rows - 1)] : 0.0;
  }

  // Multipliers on the GNSS receiver's std devs (config gnss.std_scale_*): position per fix type,
  // indexed by GnssFixType; velocity one for all.
  std::array<double, 10> gnss_position_std_scale = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  double gnss_velocity_std_scale = 1.0;
  double gnss_position_std_scale_for(GnssFixType fix) const {
    const auto i = static_cast<std::size_t>(fix);
    return i < gnss_position_std_scale.size() ? gnss_position_std_scale[i] : 1.0;
  }

  // Per-input time offsets, added to each measurement's timestamp before anything else sees it
  // (config imu/gnss/wheel.time_offset_s): puts every input on one time base.
  double imu_time_offset_s = 0.0;
  double gnss_time_offset_s = 0.0;
  double wheel_time_offset_s = 0.0;
  double time_offset_s(MeasurementKind kind) const;
  // False for the kinds the configuration switched off (magnetometer, pressure unless enabled)
  // and those switched off at run time: counted as ignored, like kinds the filter never fuses.
  bool fuses(MeasurementKind kind) const;
  // Kinds switched off at run time (Engine::set_aiding; MIP aiding control 0x0D,0x50), one bit
  // per MeasurementKind. Switching back on restores what the configuration says.
  std::uint32_t aiding_off_mask = 0;

  // Numerics and timing.
  double covariance_interval_s = 0.05;  // covariance propagated at most this far per step
  double max_latency_s = 1.0;           // measurements older than this are "too_late"
  double checkpoint_interval_s = 0.1;   // state snapshots kept for re-propagation
  double max_imu_gap_s = 1.0;           // larger IMU gaps restart the filter
  double divergence_position_std_m = 1.0e4;
};

// Options from a loaded configuration: every key of core/config (noise, geometry, estimated
// states and priors, the platform's constraints and their overrides, gates, timeouts).
FilterOptions options_from_config(const navfuse::config::Config& config);

}  // namespace navfuse::filter

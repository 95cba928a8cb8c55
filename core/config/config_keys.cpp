// The table of YAML keys (DESIGN.md "Configuration", contract) and the Config members they bind.
// Adding a key: add the member to config.hpp and one NAVFUSE_CONFIG_KEY row here. The macro
// spells the YAML path and the member path with the same tokens, so the two cannot drift apart.
#include <cstdio>
#include <limits>

#include "core/config/config.hpp"

namespace navfuse::config {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr ValueRange kNonNegative{0.0, kInf};
// Standard deviations, noise densities (and correlation times): 0 claims a perfect sensor, which makes the filter
// trust it absolutely (singular covariance, every other measurement rejected against it).
constexpr ValueRange kPositive{0.0, kInf, true};
// Mounting angles: one turn either way holds every rotation; 1e20 deg is a units or typing slip.
constexpr ValueRange kAngleDeg{-360.0, 360.0};
// Lever arms: no vehicle or vessel an IMU is fitted to puts an antenna or wheel 100 m away;
// beyond it the value is in the wrong unit (mm for m) or garbage.
constexpr ValueRange kLeverArmM{-100.0, 100.0};
// How well a point of the vehicle is known: 0 (measured exactly) to 10 m (anywhere on it).
constexpr ValueRange kPointStdM{0.0, 10.0};
// Turn-on bias priors: 1e5 deg/h (28 deg/s) is beyond the bias of any gyro a navigation filter can
// use (consumer MEMS: a few deg/s) and 100 m/s^2 (10 g) beyond any accelerometer bias; larger
// priors only overflow the covariance (1e300 squared is inf, then NaN everywhere).
constexpr ValueRange kGyroBiasStdDegHr{0.0, 1e5, true};
constexpr ValueRange kAccelBiasStdMps2{0.0, 100.0, true};

// `+[]` turns the capture-less lambda into a plain function pointer (constant-initialisable).
#define NAVFUSE_CONFIG_KEY(path, range, help) \
  KeyBinding { #path, help, range, +[](Config& c) { return &c.path; } }

// Kinematic-alignment speed threshold: above 0 (course needs motion), at most 100 m/s (a speed
// the vehicle can reach, or alignment never happens).
constexpr ValueRange kSpeedMps{0.0, 100.0, true};
constexpr ValueRange kAny{-kInf, kInf};
// Jump-free output's time constant: beyond 10 s the output would trail a corrected filter for
// most of a minute.
constexpr ValueRange kJumpBlendS{0.0, 10.0};
// A tick is a fraction of a wheel turn: beyond 10 m per count it is a distance, not a tick
// (or the count's unit is wrong).
constexpr ValueRange kTickDistanceM{0.0, 10.0};
// An odometer scale off by more than half is not an odometer the filter should calibrate.
constexpr ValueRange kScaleStd{0.0, 0.5};
// Time offsets between inputs: a few hundred ms of latency is common (USB, filtering, RTK
// processing); beyond 10 s the two clocks are not the same time base at all.
constexpr ValueRange kTimeOffsetS{-10.0, 10.0};
// The prior of an estimated offset: the state is linearised as a shift of the fix along the
// velocity (v dt, exact to 1/2 a dt^2), which holds to a centimetre for dt up to ~0.1 s at 2 m/s^2;
// an offset known to be larger belongs in gnss.time_offset_s.
constexpr ValueRange kTimeOffsetStdS{0.0, 1.0, true};
// Std-dev multipliers: above 0 (0 would claim a perfect measurement), at most 1000 (beyond it the
// measurement carries no information: leave it out instead).
constexpr ValueRange kStdScale{0.0, 1000.0, true};
// Adaptation: a window of 0.1-60 s (one GNSS epoch at 10 Hz to a minute); variance ratios from 1
// (no change) to 1e6 (std x 1000).
constexpr ValueRange kAdaptationWindowS{0.1, 60.0};
constexpr ValueRange kRatio{1.0, 1e6};
// Scale-factor priors: 10 % (1e5 ppm) is beyond any inertial sensor worth calibrating.
constexpr ValueRange kScalePpm{0.0, 1e5, true};
// Angle priors: half a turn is "nothing known"; a larger std means the same.
constexpr ValueRange kAngleStdDeg{0.0, 180.0, true};
constexpr ValueRange kLeverArmStdM{0.0, 100.0, true};
// Speeds and speed noise (NHC, ZUPT): at most 100 m/s, like the alignment threshold.
constexpr ValueRange kSpeedThresholdMps{0.0, 100.0};
// A sample gap, a latency, a detector window: above 0 and at most 10 s (the history kept for late
// measurements grows with max_latency_s; a 10 s window never sees a stop).
constexpr ValueRange kShortSpanS{0.0, 10.0, true};
constexpr ValueRange kLatencyS{0.0, 10.0};  // 0: no re-propagation of late measurements
// GNSS loss and levelling timeouts: above 0, at most 10 minutes.
constexpr ValueRange kTimeoutS{0.0, 600.0, true};
constexpr ValueRange kHoldS{0.0, 600.0};  // 0: off
// A GNSS step worth holding fixes out for: at most 100 m (beyond it no multipath reaches).
constexpr ValueRange kJumpM{0.0, 100.0};
// Gyro threshold for "stationary": at most 10 rad/s (a spinning wheel).
constexpr ValueRange kRateRadS{0.0, 10.0, true};
constexpr ValueRange kAccelStdMps2{0.0, 100.0, true};
// Chi-square gates: below 1 (the 68 % quantile for one dimension) the gate rejects healthy
// measurements; 1e6 is in effect no gate.
constexpr ValueRange kChi2{1.0, 1e6};

// Magnetic heading noise: above 0, at most 180 deg (beyond it the heading says nothing).
constexpr ValueRange kHeadingStdDeg{0.0, 180.0, true};
// Declination: -180..180 deg covers the whole globe, poles included.
constexpr ValueRange kDeclinationDeg{-180.0, 180.0};
// The earth's field is 0.25-0.65 gauss; a hard-iron offset beyond 10 gauss is a unit slip
// (uT or nT for gauss) or a sensor that saturates anyway.
constexpr ValueRange kHardIronGauss{-10.0, 10.0};
// Pressure height noise: above 0, at most 1000 m (beyond it, leave the barometer out).
constexpr ValueRange kBaroStdM{0.0, 1000.0, true};

const KeyBinding kKeys[] = {
    NAVFUSE_CONFIG_KEY(platform, kAny,
                       "generic | land | pedestrian | airborne | marine: which motion constraints apply"),
    NAVFUSE_CONFIG_KEY(imu.mounting_rpy_deg, kAngleDeg,
                       "sensor -> vehicle roll, pitch, yaw (deg, 3-2-1)"),
    NAVFUSE_CONFIG_KEY(imu.gyro_arw_deg_rthr, kPositive, "gyro angle random walk (deg/sqrt(h))"),
    NAVFUSE_CONFIG_KEY(imu.gyro_bias_instability_deg_hr, kNonNegative,
                       "gyro in-run bias instability (deg/h)"),
    NAVFUSE_CONFIG_KEY(imu.gyro_bias_corr_time_s, kPositive,
                       "gyro bias Gauss-Markov correlation time (s)"),
    NAVFUSE_CONFIG_KEY(imu.accel_vrw_mps_rthr, kPositive,
                       "accel velocity random walk (m/s/sqrt(h))"),
    NAVFUSE_CONFIG_KEY(imu.accel_bias_instability_mps2, kNonNegative,
                       "accel in-run bias instability (m/s^2)"),
    NAVFUSE_CONFIG_KEY(imu.accel_bias_corr_time_s, kPositive,
                       "accel bias Gauss-Markov correlation time (s)"),
    NAVFUSE_CONFIG_KEY(imu.initial_gyro_bias_std_deg_hr, kGyroBiasStdDegHr,
                       "turn-on gyro bias uncertainty, 1 sigma (deg/h)"),
    NAVFUSE_CONFIG_KEY(imu.initial_accel_bias_std_mps2, kAccelBiasStdMps2,
                       "turn-on accel bias uncertainty, 1 sigma (m/s^2)"),
    NAVFUSE_CONFIG_KEY(imu.time_offset_s, kTimeOffsetS,
                       "added to IMU timestamps to put them on GNSS time (s; -0.125: IMU stamps 125 ms late)"),
    NAVFUSE_CONFIG_KEY(imu.max_gap_s, kShortSpanS, "a longer gap between IMU samples restarts the filter (s)"),
    NAVFUSE_CONFIG_KEY(imu.estimate_gyro_scale, kAny, "estimate gyro scale factors (true | false)"),
    NAVFUSE_CONFIG_KEY(imu.initial_gyro_scale_std_ppm, kScalePpm, "gyro scale factor prior, 1 sigma (ppm)"),
    NAVFUSE_CONFIG_KEY(imu.estimate_accel_scale, kAny, "estimate accel scale factors (true | false)"),
    NAVFUSE_CONFIG_KEY(imu.initial_accel_scale_std_ppm, kScalePpm, "accel scale factor prior, 1 sigma (ppm)"),
    NAVFUSE_CONFIG_KEY(imu.estimate_mounting, kAny,
                       "estimate residual mounting pitch and yaw, seen by odometry and NHC (true | false)"),
    NAVFUSE_CONFIG_KEY(imu.initial_mounting_std_deg, kAngleStdDeg, "residual mounting prior, 1 sigma (deg)"),
    NAVFUSE_CONFIG_KEY(gnss.lever_arm_m, kLeverArmM, "primary antenna, vehicle frame FRD (m)"),
    NAVFUSE_CONFIG_KEY(gnss.secondary_lever_arm_m, kLeverArmM,
                       "secondary antenna: dual-antenna heading baseline, and where the fixes of "
                       "receiver 2 (GNSS2, receiver_id 1) are measured; vehicle frame FRD (m)"),
    NAVFUSE_CONFIG_KEY(gnss.baseline_std_m, kLeverArmStdM,
                       "dual-antenna baseline uncertainty per axis, 1 sigma, sent by --configure-device "
                       "(VN-300 Reg 93) (m)"),
    NAVFUSE_CONFIG_KEY(gnss.time_offset_s, kTimeOffsetS,
                       "added to GNSS timestamps (s; -0.1: fixes stamped 100 ms after their epoch)"),
    NAVFUSE_CONFIG_KEY(gnss.std_scale_rtk_fixed, kStdScale, "multiplier on RTK-fixed position std devs"),
    NAVFUSE_CONFIG_KEY(gnss.std_scale_rtk_float, kStdScale, "multiplier on RTK-float position std devs"),
    NAVFUSE_CONFIG_KEY(gnss.std_scale_ppp, kStdScale, "multiplier on PPP position std devs"),
    NAVFUSE_CONFIG_KEY(gnss.std_scale_dgnss, kStdScale, "multiplier on DGNSS/SBAS position std devs"),
    NAVFUSE_CONFIG_KEY(gnss.std_scale_single, kStdScale, "multiplier on single-point position std devs"),
    NAVFUSE_CONFIG_KEY(gnss.velocity_std_scale, kStdScale, "multiplier on GNSS velocity std devs"),
    NAVFUSE_CONFIG_KEY(gnss.timeout_s, kTimeoutS, "no position aiding for longer: dead reckoning (s)"),
    NAVFUSE_CONFIG_KEY(gnss.recovery_s, kTimeoutS,
                       "every fix rejected for longer: re-anchor the position to GNSS (s)"),
    NAVFUSE_CONFIG_KEY(gnss.jump_hold_s, kHoldS,
                       "fixes that stepped away from the inertial track (multipath, a wrong RTK fix) are "
                       "rejected until they return to it, for at most this long (s; 0: no step check)"),
    NAVFUSE_CONFIG_KEY(gnss.jump_min_m, kJumpM, "smaller steps between fixes are not held out (m)"),
    NAVFUSE_CONFIG_KEY(gnss.estimate_lever_arm, kAny, "estimate the primary antenna lever arm (true | false)"),
    NAVFUSE_CONFIG_KEY(gnss.initial_lever_arm_std_m, kLeverArmStdM, "lever arm prior per axis, 1 sigma (m)"),
    NAVFUSE_CONFIG_KEY(gnss.estimate_time_offset, kAny,
                       "estimate the GNSS-to-IMU time offset left after time_offset_s (true | false)"),
    NAVFUSE_CONFIG_KEY(gnss.initial_time_offset_std_s, kTimeOffsetStdS, "time offset prior, 1 sigma (s)"),
    NAVFUSE_CONFIG_KEY(wheel.lever_arm_m, kLeverArmM,
                       "speed measurement point (e.g. rear axle centre), vehicle frame FRD (m)"),
    NAVFUSE_CONFIG_KEY(wheel.speed_std_mps, kPositive, "wheel speed noise, 1 sigma (m/s)"),
    NAVFUSE_CONFIG_KEY(wheel.m_per_tick, kTickDistanceM,
                       "distance per wheel / vehicle tick or odometer pulse (UM220 odometer_m_per_pulse) "
                       "(m; 0: ticks not fused)"),
    NAVFUSE_CONFIG_KEY(wheel.initial_scale_std, kScaleStd,
                       "odometer scale error prior, 1 sigma (fraction; 0: scale not estimated)"),
    NAVFUSE_CONFIG_KEY(wheel.time_offset_s, kTimeOffsetS, "added to wheel speed and tick timestamps (s)"),
    NAVFUSE_CONFIG_KEY(alignment.min_speed_mps, kSpeedMps,
                       "GNSS speed for heading from course (m/s; ~: 2, pedestrian 0.5)"),
    NAVFUSE_CONFIG_KEY(alignment.initial_heading_deg, kAngleDeg,
                       "known heading at start (deg from north; ~: align by itself)"),
    NAVFUSE_CONFIG_KEY(alignment.initial_heading_std_deg, kAngleStdDeg,
                       "1 sigma of initial_heading_deg (deg)"),
    NAVFUSE_CONFIG_KEY(alignment.initial_tilt_std_deg, kAngleStdDeg,
                       "roll and pitch 1 sigma once levelled (deg; ~: from the accel bias prior at rest, "
                       "2 in motion)"),
    NAVFUSE_CONFIG_KEY(alignment.initial_velocity_std_mps, kSpeedMps,
                       "velocity 1 sigma per axis once levelled (m/s; ~: 0.05 at rest, 5 in motion)"),
    NAVFUSE_CONFIG_KEY(alignment.course, kAny,
                       "heading from the course over ground (true | false; ~: land platform only)"),
    NAVFUSE_CONFIG_KEY(alignment.level_time_s, kShortSpanS, "stationary time averaged for levelling (s)"),
    NAVFUSE_CONFIG_KEY(alignment.level_timeout_s, kTimeoutS,
                       "level from whatever was seen when never stationary this long (s)"),
    NAVFUSE_CONFIG_KEY(nhc.enabled, kAny,
                       "non-holonomic constraint (true | false; ~: land platform only)"),
    NAVFUSE_CONFIG_KEY(nhc.lever_arm_m, kLeverArmM,
                       "the point that does not slip sideways (a car's rear-axle centre), vehicle frame "
                       "FRD (m; ~: wheel.lever_arm_m)"),
    NAVFUSE_CONFIG_KEY(nhc.lever_arm_std_m, kPointStdM,
                       "how well that point is known, 1 sigma per axis (m; ~: 0 when nhc.lever_arm_m or a "
                       "non-zero wheel.lever_arm_m gives it, else 1.5, 0.5, 0.5: a guess at the IMU)"),
    NAVFUSE_CONFIG_KEY(nhc.lateral_std_mps, kSpeedMps, "sideways velocity at the constraint point, 1 sigma (m/s)"),
    NAVFUSE_CONFIG_KEY(nhc.vertical_std_mps, kSpeedMps, "vertical velocity at the constraint point, 1 sigma (m/s)"),
    NAVFUSE_CONFIG_KEY(nhc.min_speed_mps, kSpeedThresholdMps, "applied only above this speed (m/s)"),
    NAVFUSE_CONFIG_KEY(nhc.interval_s, kShortSpanS, "time between constraint updates (s)"),
    NAVFUSE_CONFIG_KEY(zupt.enabled, kAny,
                       "zero-velocity and zero-rate updates at stops (true | false; ~: generic, land, "
                       "pedestrian platforms)"),
    NAVFUSE_CONFIG_KEY(zupt.std_mps, kSpeedMps, "zero-velocity update noise, 1 sigma (m/s)"),
    NAVFUSE_CONFIG_KEY(zupt.window_s, kShortSpanS, "stationary detector window (s)"),
    NAVFUSE_CONFIG_KEY(zupt.max_rate_rad_s, kRateRadS, "stationary: mean |angular rate| below this (rad/s)"),
    NAVFUSE_CONFIG_KEY(zupt.max_accel_std_mps2, kAccelStdMps2,
                       "stationary: specific-force scatter below this (m/s^2)"),
    NAVFUSE_CONFIG_KEY(zupt.max_speed_mps, kSpeedMps,
                       "stationary: odometry, GNSS and filter speed below this (m/s)"),
    NAVFUSE_CONFIG_KEY(gates.chi2_1d, kChi2, "chi-square gate of 1-D updates (speed, heading, ...)"),
    NAVFUSE_CONFIG_KEY(gates.chi2_2d, kChi2, "chi-square gate of 2-D updates (NHC, ...)"),
    NAVFUSE_CONFIG_KEY(gates.chi2_3d, kChi2, "chi-square gate of 3-D updates (GNSS position, velocity, ZUPT)"),
    NAVFUSE_CONFIG_KEY(gates.gnss_jump, kChi2,
                       "chi-square test of the step between consecutive GNSS fixes of one fix type against "
                       "the inertial track"),
    NAVFUSE_CONFIG_KEY(gates.gnss_position, kChi2, "chi-square gate of GNSS position updates (~: chi2_3d)"),
    NAVFUSE_CONFIG_KEY(gates.gnss_velocity, kChi2, "chi-square gate of GNSS velocity updates (~: chi2_3d)"),
    NAVFUSE_CONFIG_KEY(gates.gnss_heading, kChi2, "chi-square gate of dual-antenna heading updates (~: chi2_1d)"),
    NAVFUSE_CONFIG_KEY(gates.odometry, kChi2,
                       "chi-square gate of wheel speed, vehicle speed and wheel tick updates (~: chi2_1d)"),
    NAVFUSE_CONFIG_KEY(gates.nhc, kChi2, "chi-square gate of non-holonomic constraint updates (~: chi2_2d)"),
    NAVFUSE_CONFIG_KEY(gates.stationary, kChi2, "chi-square gate of zero-velocity and zero-rate updates (~: chi2_3d)"),
    NAVFUSE_CONFIG_KEY(gates.gravity, kChi2, "chi-square gate of accelerometer tilt updates (~: chi2_3d)"),
    NAVFUSE_CONFIG_KEY(gates.pressure, kChi2, "chi-square gate of barometric height updates (~: chi2_1d)"),
    NAVFUSE_CONFIG_KEY(gates.magnetometer, kChi2, "chi-square gate of magnetic heading updates (~: chi2_1d)"),
    NAVFUSE_CONFIG_KEY(gates.external_position, kChi2,
                       "chi-square gate of external position updates (~: by their rows)"),
    NAVFUSE_CONFIG_KEY(gates.external_velocity, kChi2,
                       "chi-square gate of external velocity updates (~: by their rows)"),
    NAVFUSE_CONFIG_KEY(gates.external_heading, kChi2, "chi-square gate of external heading updates (~: chi2_1d)"),
    NAVFUSE_CONFIG_KEY(timing.max_latency_s, kLatencyS,
                       "older measurements are rejected as too_late (s; 0: no re-propagation)"),
    NAVFUSE_CONFIG_KEY(adaptation.window_s, kAdaptationWindowS,
                       "innovations within this span decide that the filter is overconfident (s)"),
    NAVFUSE_CONFIG_KEY(adaptation.inflate_ratio, kRatio,
                       "median NIS per dimension that re-inflates P (3: innovations 1.7x their std)"),
    NAVFUSE_CONFIG_KEY(adaptation.max_process_noise_scale, kRatio,
                       "largest multiplier on the IMU noise variances (1: data sheet only)"),
    NAVFUSE_CONFIG_KEY(adaptation.max_measurement_noise_scale, kRatio,
                       "largest multiplier on GNSS reported variances when they prove optimistic (1: as reported)"),
    NAVFUSE_CONFIG_KEY(magnetometer.heading_std_deg, kHeadingStdDeg,
                       "magnetic heading noise, 1 sigma (deg; ~: magnetometer not fused)"),
    NAVFUSE_CONFIG_KEY(magnetometer.declination_deg, kDeclinationDeg,
                       "magnetic declination, east positive (deg; ~: GeographicLib magnetic model if installed)"),
    NAVFUSE_CONFIG_KEY(magnetometer.hard_iron_gauss, kHardIronGauss,
                       "installation's constant field, subtracted, sensor frame (gauss)"),
    NAVFUSE_CONFIG_KEY(baro.height_std_m, kBaroStdM,
                       "pressure height noise, 1 sigma (m; ~: barometer not fused)"),
    NAVFUSE_CONFIG_KEY(accel_tilt.enabled, kAny,
                       "gravity as roll/pitch reference while nothing observes velocity (true | false; "
                       "~: pedestrian and marine platforms)"),
    NAVFUSE_CONFIG_KEY(accel_tilt.std_mps2, kAccelStdMps2,
                       "the vehicle's own acceleration, taken as noise, 1 sigma (m/s^2)"),
    NAVFUSE_CONFIG_KEY(accel_tilt.max_deviation_mps2, kAccelStdMps2,
                       "| |specific force| - g | above this: manoeuvring, not used (m/s^2)"),
    NAVFUSE_CONFIG_KEY(output.rate_hz, kNonNegative, "pose output rate (Hz, 0 = every IMU sample)"),
    NAVFUSE_CONFIG_KEY(output.jump_blend_s, kJumpBlendS,
                       "a position correction of at least jump_blend_min_m reaches the output over this time "
                       "constant instead of in one step (s; 0: the output jumps with the filter)"),
    NAVFUSE_CONFIG_KEY(output.jump_blend_min_m, kNonNegative,
                       "smallest position correction the output blends (m)"),
};

#undef NAVFUSE_CONFIG_KEY

}  // namespace

std::span<const KeyBinding> key_table() { return kKeys; }

std::string ValueRange::describe() const {
  char text[96];
  if (max == kInf) {
    std::snprintf(text, sizeof text, "%s %g", min_exclusive ? ">" : ">=", min);
  } else {
    std::snprintf(text, sizeof text, "in %c%g, %g]", min_exclusive ? '(' : '[', min, max);
  }
  return text;
}

}  // namespace navfuse::config

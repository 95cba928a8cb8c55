// navfuse configuration: the YAML keys of DESIGN.md (contract) as plain data, with device
// profiles supplying defaults. Loading rejects unknown keys and wrong types with an error that
// names the key (e.g. "imu.gyro_arw_deg_rthr: expected a number, got 'fast'").
//
// Units are in the key names and kept as written in YAML here (deg, deg/hr, ...); the filter
// converts to SI when it builds its noise model.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

namespace navfuse::config {

enum class DeviceProfile { kGeneric, kCv7, kVn300, kUm220, kFusionEngine };
std::string_view to_string(DeviceProfile p);
std::optional<DeviceProfile> device_profile_from_string(std::string_view name);

// What carries the sensors; it decides which motion constraints the filter may assume
// (core/config/platform.cpp). land: non-holonomic constraint, wheel speed, zero-velocity updates;
// pedestrian (walked or handheld): zero-velocity and zero-rate updates at stops, no NHC;
// airborne, marine: neither (an aircraft or a boat at "rest" still moves with air or water).
enum class Platform { kGeneric, kLand, kPedestrian, kAirborne, kMarine };
std::string_view to_string(Platform p);
std::optional<Platform> platform_from_string(std::string_view name);

using Vec3 = std::array<double, 3>;

struct ImuConfig {
  Vec3 mounting_rpy_deg{0, 0, 0};  // sensor -> vehicle, 3-2-1
  double gyro_arw_deg_rthr = 0.08;
  double gyro_bias_instability_deg_hr = 1.5;
  double gyro_bias_corr_time_s = 300;
  double accel_vrw_mps_rthr = 0.02;
  double accel_bias_instability_mps2 = 2.0e-5;
  double accel_bias_corr_time_s = 300;
  double initial_gyro_bias_std_deg_hr = 20;
  double initial_accel_bias_std_mps2 = 0.01;
  double time_offset_s = 0.0;  // added to IMU timestamps to put them on the GNSS time base
  double max_gap_s = 1.0;      // a longer gap between samples restarts the filter
  // Estimated calibration states and their priors (filter/state_layout.hpp).
  bool estimate_gyro_scale = false;
  double initial_gyro_scale_std_ppm = 1000;
  bool estimate_accel_scale = false;
  double initial_accel_scale_std_ppm = 1000;
  bool estimate_mounting = false;  // residual mounting pitch and yaw
  double initial_mounting_std_deg = 1.0;
};

struct GnssConfig {
  Vec3 lever_arm_m{0, 0, 0};            // primary antenna, vehicle frame
  Vec3 secondary_lever_arm_m{0, 0, 0};  // dual-antenna heading, if any
  // Uncertainty of the baseline (secondary minus primary) per axis, for devices that take one
  // (VN-300 Reg 93: its default 0.0254 m; Reg 97 baseline estimation needs it >= 1.75 % of the
  // largest baseline component, VN-300 ICD L5147-5175).
  double baseline_std_m = 0.0254;
  double time_offset_s = 0.0;           // added to GNSS timestamps (receiver latency, s)
  // Multipliers on the receiver's own position std devs, per fix type (its std devs are often
  // optimistic for some fix types: RTK float, single point); velocity std devs have one.
  double std_scale_rtk_fixed = 1.0;
  double std_scale_rtk_float = 1.0;
  double std_scale_ppp = 1.0;
  double std_scale_dgnss = 1.0;   // DGNSS and SBAS
  double std_scale_single = 1.0;  // 2-D and 3-D single point
  double velocity_std_scale = 1.0;
  double timeout_s = 2.0;   // no position aiding for longer: dead reckoning
  double recovery_s = 3.0;  // fixes rejected for longer: re-anchor to GNSS
  // Fixes that stepped away from the inertial track (multipath, a wrong RTK fix) are rejected
  // until they return to it, for at most this long (s; 0: no step check).
  double jump_hold_s = 10.0;
  double jump_min_m = 0.1;  // smaller steps are not held out
  bool estimate_lever_arm = false;  // primary antenna lever arm as a state
  double initial_lever_arm_std_m = 0.1;
  // The GNSS-to-IMU time offset left after time_offset_s, as a state (a rig whose latency is not
  // known, or drifts with the receiver's load).
  bool estimate_time_offset = false;
  double initial_time_offset_std_s = 0.05;
};

struct WheelConfig {
  Vec3 lever_arm_m{0, 0, 0};  // speed measurement point (e.g. rear axle centre)
  double speed_std_mps = 0.05;
  // Distance per count of a tick counter: wheel encoders (FusionEngine WheelTickInput), vehicle
  // tick counters (VehicleTickInput) and the UM220's odometer pulses (its odometer_m_per_pulse,
  // which the device calibrates and never reports). 0: tick counts are not fused.
  double m_per_tick = 0.0;
  // Prior 1-sigma of the odometer scale error (fraction; 0.02 = 2 %); 0: not estimated.
  double initial_scale_std = 0.02;
  double time_offset_s = 0.0;  // added to wheel speed / tick timestamps (s)
};

// Heading initialisation. Unset (nullopt, `~` in YAML) means "the platform's default" or "none".
struct AlignmentConfig {
  // Kinematic alignment takes the heading from the GNSS course above this horizontal speed;
  // unset: 2 m/s, or 0.5 m/s on a pedestrian platform.
  std::optional<double> min_speed_mps;
  std::optional<double> initial_heading_deg;  // known heading at start (deg from north)
  double initial_heading_std_deg = 5.0;       // its 1-sigma uncertainty
  // Roll/pitch and velocity uncertainty once levelled; unset: derived (tilt from the accelerometer
  // bias prior and noise averaged at rest, else 2 deg; velocity 0.05 m/s at rest, else 5 m/s).
  std::optional<double> initial_tilt_std_deg;
  std::optional<double> initial_velocity_std_mps;
  // Heading from the course over ground; unset: on a land platform only (it assumes motion
  // along the vehicle's x axis).
  std::optional<bool> course;
  double level_time_s = 1.0;      // stationary time averaged for levelling
  double level_timeout_s = 10.0;  // level from whatever was seen if never stationary that long
};

// Non-holonomic constraint (Groves 2nd ed. §13.1.3): no sideways or vertical velocity at the
// wheel point. Unset `enabled`: on for a land platform only.
struct NhcConfig {
  std::optional<bool> enabled;
  // The point that does not slip sideways (a car's rear-axle centre); unset: wheel.lever_arm_m.
  std::optional<Vec3> lever_arm_m;
  // How well that point is known, 1 sigma per vehicle axis (m). Unset: 0 when lever_arm_m or a
  // non-zero wheel.lever_arm_m gives it, else kUnknownNonSlipPointStdM (the IMU is only a guess).
  std::optional<Vec3> lever_arm_std_m;
  double lateral_std_mps = 0.1;
  double vertical_std_mps = 0.1;
  double min_speed_mps = 1.0;  // below it stops are left to zero-velocity updates
  double interval_s = 0.1;
};

// Stationary detection and zero-velocity / zero-rate updates. Unset `enabled`: on for generic,
// land and pedestrian platforms (stops are detected in any case).
struct ZuptConfig {
  std::optional<bool> enabled;
  double std_mps = 0.02;
  double window_s = 0.2;              // detector window
  double max_rate_rad_s = 0.01;       // mean |rate| over the window below this ...
  double max_accel_std_mps2 = 0.05;   // ... and specific-force scatter below this ...
  double max_speed_mps = 0.3;         // ... and odometry / GNSS / filter speed below this
};

// Chi-square innovation gates by measurement dimension (the 99.99 % quantiles by default).
struct GatesConfig {
  double chi2_1d = 15.14;
  double chi2_2d = 18.42;
  double chi2_3d = 21.11;
  // The step between consecutive GNSS fixes of one fix type against the inertial track
  // (filter/control/gnss_jump_check.hpp): about the 1e-6 tail of chi-square(3).
  double gnss_jump = 30.0;
  // A chi-square gate of its own per aiding source, for every update of it whatever its rows
  // (unset: by dimension above). A receiver known to report multipath-free fixes can be held to a
  // tighter gate than the odometer, or a noisy external aid given a looser one.
  std::optional<double> gnss_position;
  std::optional<double> gnss_velocity;
  std::optional<double> gnss_heading;
  std::optional<double> odometry;  // wheel speed, vehicle speed, wheel ticks
  std::optional<double> nhc;
  std::optional<double> stationary;  // zero-velocity and zero-rate updates
  std::optional<double> gravity;     // accelerometer tilt reference
  std::optional<double> pressure;
  std::optional<double> magnetometer;
  std::optional<double> external_position;
  std::optional<double> external_velocity;
  std::optional<double> external_heading;
};

struct TimingConfig {
  double max_latency_s = 1.0;  // older measurements are rejected as too_late
};

// Innovation-based adaptation (filter/control/innovation_adaptation.hpp).
struct AdaptationConfig {
  double window_s = 1.0;                   // innovations looked at for "persistently"
  double inflate_ratio = 3.0;              // median NIS per dimension that re-inflates P
  double max_process_noise_scale = 100.0;  // 1: data-sheet noise only, no adaptation of Q
  double max_measurement_noise_scale = 100.0;  // 1: the receivers' std devs as reported
};

// Magnetometer heading aiding (filter/control/magnetometer_control.hpp). Off unless a heading
// std is given: a magnetometer near steel or motors is wrong by tens of degrees, so fusing it is
// the user's decision for the installation.
struct MagnetometerConfig {
  std::optional<double> heading_std_deg;  // 1-sigma of the magnetic heading; unset: not fused
  // Magnetic declination (east positive). Unset: GeographicLib's magnetic model at the current
  // position when its data is installed (geographiclib-get-magnetic), else not fused.
  std::optional<double> declination_deg;
  Vec3 hard_iron_gauss{0, 0, 0};  // constant field of the installation, sensor frame, subtracted
};

// Barometric height aiding (filter/control/baro_control.hpp): relative height only, anchored to
// the filter's height when first fused. Off unless a height std is given.
struct BaroConfig {
  std::optional<double> height_std_m;  // 1-sigma of the pressure height; unset: not fused
};

// Accelerometer tilt aiding (filter/control/tilt_control.hpp): gravity as the roll and pitch
// reference while nothing observes velocity (no position, GNSS velocity, odometry or stop for
// gnss.timeout_s), as an AHRS or vertical gyro does; the vehicle's own acceleration is its noise.
// Unset `enabled`: on for pedestrian (handheld) and marine platforms, whose accelerations swing
// about zero (steps, waves); a car's or an aircraft's last for seconds and would read as tilt.
struct AccelTiltConfig {
  std::optional<bool> enabled;
  double std_mps2 = 0.5;            // the vehicle's own acceleration, as noise, 1 sigma
  double max_deviation_mps2 = 1.0;  // | |f| - g | beyond this: manoeuvring, not used
};

struct OutputConfig {
  double rate_hz = 100;  // pose output rate (0 = every IMU sample)
  // A position correction of at least jump_blend_min_m reaches the output over the time constant
  // jump_blend_s instead of in one step (filter/output_blend.hpp; 0 s: the output jumps).
  double jump_blend_s = 0.25;
  double jump_blend_min_m = 0.1;
};

// The in-class initialisers above are the DESIGN.md example values; the defaults a loaded config
// actually starts from are defaults_for(profile) (core/config/device_profiles.cpp).
struct Config {
  DeviceProfile device = DeviceProfile::kGeneric;
  Platform platform = Platform::kGeneric;
  ImuConfig imu;
  GnssConfig gnss;
  WheelConfig wheel;
  AlignmentConfig alignment;
  NhcConfig nhc;
  ZuptConfig zupt;
  GatesConfig gates;
  TimingConfig timing;
  AdaptationConfig adaptation;
  MagnetometerConfig magnetometer;
  BaroConfig baro;
  AccelTiltConfig accel_tilt;
  OutputConfig output;
};

// Thrown by the loaders; what() is one line naming the file, key and problem.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Defaults for a device profile (before any YAML key is applied).
Config defaults_for(DeviceProfile profile);
// Parses YAML text: `device:` (if present) selects the profile defaults, then every other key
// overrides them. `source_name` is used in error messages.
Config load_from_string(const std::string& yaml_text, const std::string& source_name = "<config>");
Config load_from_file(const std::string& path);

// The effective configuration as YAML that load_from_string() reads back to an equal Config:
// every key, in DESIGN.md order, each with a comment giving its meaning and unit. Numbers are
// printed in shortest round-trip form, so nothing is lost.
std::string to_yaml(const Config& config);

// ---- The key table (core/config/config_keys.cpp) --------------------------------------------
// Every YAML key except `device` is one row binding a dotted path to a Config member; the
// loader, the unknown-key check and to_yaml() all walk this table, so adding a key is one row.

// The range a value must lie in to describe a real installation (non-finite values never do).
// The loader refuses a value outside it, naming the key: such values do not tune the solution,
// they wreck it (a 1e9 m lever arm gave a 1e9 m error reported with a 1.5 m std).
struct ValueRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;  // (min, max] rather than [min, max]

  bool contains(double v) const { return (min_exclusive ? v > min : v >= min) && v <= max; }
  std::string describe() const;  // ">= 0", "> 0", "in [-100, 100]", "in (0, 100]"
};

struct KeyBinding {
  std::string_view key;   // dotted YAML path, e.g. "imu.gyro_arw_deg_rthr"
  std::string_view help;  // meaning and unit; printed as a comment by to_yaml()
  ValueRange range;
  // Where the value lives: a scalar, a fixed-length array of 3 (YAML flow sequence), an optional
  // scalar or array (`~` = unset), the platform name, or a switch (`true` / `false` only;
  // optional: `~` leaves it to the platform).
  std::variant<double* (*)(Config&), Vec3* (*)(Config&), std::optional<double>* (*)(Config&),
               Platform* (*)(Config&), bool* (*)(Config&), std::optional<bool>* (*)(Config&),
               std::optional<Vec3>* (*)(Config&)>
      target;
};

std::span<const KeyBinding> key_table();

}  // namespace navfuse::config

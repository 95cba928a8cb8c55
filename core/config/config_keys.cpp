// The table of YAML keys (DESIGN.md "Configuration", contract) and the Config members they bind.
// Adding a key: add the member to config.hpp and one NAVFUSE_CONFIG_KEY row here. The macro
// spells the YAML path and the member path with the same tokens, so the two cannot drift apart.
#include "core/config/config.hpp"

namespace navfuse::config {
namespace {

// `+[]` turns the capture-less lambda into a plain function pointer (constant-initialisable).
#define NAVFUSE_CONFIG_KEY(path, check, help) \
  KeyBinding { #path, help, ValueCheck::check, +[](Config& c) { return &c.path; } }

const KeyBinding kKeys[] = {
    NAVFUSE_CONFIG_KEY(platform, kAny,
                       "land | pedestrian | airborne | marine: which motion constraints apply"),
    NAVFUSE_CONFIG_KEY(imu.mounting_rpy_deg, kAny,
                       "sensor -> vehicle roll, pitch, yaw (deg, 3-2-1)"),
    NAVFUSE_CONFIG_KEY(imu.gyro_arw_deg_rthr, kNonNegative, "gyro angle random walk (deg/sqrt(h))"),
    NAVFUSE_CONFIG_KEY(imu.gyro_bias_instability_deg_hr, kNonNegative,
                       "gyro in-run bias instability (deg/h)"),
    NAVFUSE_CONFIG_KEY(imu.gyro_bias_corr_time_s, kPositive,
                       "gyro bias Gauss-Markov correlation time (s)"),
    NAVFUSE_CONFIG_KEY(imu.accel_vrw_mps_rthr, kNonNegative,
                       "accel velocity random walk (m/s/sqrt(h))"),
    NAVFUSE_CONFIG_KEY(imu.accel_bias_instability_mps2, kNonNegative,
                       "accel in-run bias instability (m/s^2)"),
    NAVFUSE_CONFIG_KEY(imu.accel_bias_corr_time_s, kPositive,
                       "accel bias Gauss-Markov correlation time (s)"),
    NAVFUSE_CONFIG_KEY(imu.initial_gyro_bias_std_deg_hr, kNonNegative,
                       "turn-on gyro bias uncertainty, 1 sigma (deg/h)"),
    NAVFUSE_CONFIG_KEY(imu.initial_accel_bias_std_mps2, kNonNegative,
                       "turn-on accel bias uncertainty, 1 sigma (m/s^2)"),
    NAVFUSE_CONFIG_KEY(gnss.lever_arm_m, kAny, "primary antenna, vehicle frame FRD (m)"),
    NAVFUSE_CONFIG_KEY(gnss.secondary_lever_arm_m, kAny,
                       "secondary antenna for dual-antenna heading, vehicle frame FRD (m)"),
    NAVFUSE_CONFIG_KEY(wheel.lever_arm_m, kAny,
                       "speed measurement point (e.g. rear axle centre), vehicle frame FRD (m)"),
    NAVFUSE_CONFIG_KEY(wheel.speed_std_mps, kNonNegative, "wheel speed noise, 1 sigma (m/s)"),
    NAVFUSE_CONFIG_KEY(alignment.min_speed_mps, kSpeedMps,
                       "GNSS speed for heading from course (m/s; ~: 2, pedestrian 0.5)"),
    NAVFUSE_CONFIG_KEY(alignment.initial_heading_deg, kAngleDeg,
                       "known heading at start (deg from north; ~: align by itself)"),
    NAVFUSE_CONFIG_KEY(output.rate_hz, kNonNegative, "pose output rate (Hz, 0 = every IMU sample)"),
};

#undef NAVFUSE_CONFIG_KEY

}  // namespace

std::span<const KeyBinding> key_table() { return kKeys; }

}  // namespace navfuse::config

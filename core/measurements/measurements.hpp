// Normalised measurement types: what every front-end produces and the filter consumes.
//
// Conventions (DESIGN.md, contract): SI units, geodetic WGS-84 positions in radians and
// ellipsoidal metres, local NED navigation frame, FRD vehicle frame. Front-ends convert from
// their protocol's units at the boundary; nothing past this header sees degrees, g or cm.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <variant>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/time/gps_time.hpp"

namespace navfuse {

// Where a measurement's timestamp came from. The filter only fuses measurements whose time is on
// the same base as its IMU stream; `kDeviceMonotonic` times are mapped to GPS by a ClockModel.
enum class TimeSource : std::uint8_t {
  kGps = 0,              // GPS time (ns since 1980-01-06), from the device's GNSS-disciplined clock
  kDeviceMonotonic = 1,  // the device's own running clock (e.g. VN TimeStartup, MIP 0xD7 ticks)
  kHostArrival = 2,      // the host clock when the bytes arrived (last resort, has transport jitter)
  kUnknown = 3,
};

// Header carried by every measurement.
struct MeasurementHeader {
  std::int64_t time_ns = 0;  // measurement (not arrival) time on `time_source`'s base
  TimeSource time_source = TimeSource::kUnknown;
  std::uint16_t stream_id = 0;  // which input stream produced it (set by the app, 0 by default)
  std::uint32_t valid = 0;      // validity mask; bit meanings are defined by each type below
};

// ---------------------------------------------------------------------------------------------
// Inertial
enum class ImuQuantity : std::uint8_t {
  kRates = 0,       // gyro in rad/s, accel (specific force) in m/s^2, instantaneous
  kIncrements = 1,  // delta angle in rad and delta velocity in m/s over dt_s (see ImuIncrements)
};
// What a device's increments already contain. The two differ by second-order terms that are not
// small in a turn: 0.5 dtheta x dv per interval is ~1e-3 m/s^2 at 15 m/s, 9 deg/s, 200 Hz.
enum class ImuIncrements : std::uint8_t {
  // Time integrals of the rate and the specific force in the moving sensor frame (MIP 0x80
  // 0x07/0x08 "time integral", KF-GINS text files, rates times dt): the filter adds the coning,
  // rotation and sculling terms itself.
  kRawIntegrals = 0,
  // Already coning- and sculling-integrated by the device: the attitude change's rotation vector,
  // and the velocity change in the frame at the interval's start (VN-300 DeltaTheta/DeltaVel,
  // "conning and sculling integration performed onboard", ICD 2.4.7-2.4.8). Added again, the
  // rotation term biases every turn.
  kCompensated = 1,
};
enum class SensorFrame : std::uint8_t {
  kSensor = 0,   // the IMU case frame: the configured mounting rotates it into the vehicle frame
  kVehicle = 1,  // already in the FRD vehicle frame (device applied its own mounting)
};
struct ImuSample {
  MeasurementHeader header;
  ImuQuantity quantity = ImuQuantity::kRates;
  SensorFrame frame = SensorFrame::kSensor;
  Eigen::Vector3d gyro = Eigen::Vector3d::Zero();   // rad/s or rad (see quantity)
  Eigen::Vector3d accel = Eigen::Vector3d::Zero();  // m/s^2 or m/s (see quantity)
  double dt_s = 0.0;         // integration interval for increments; nominal period for rates (0: unknown)
  ImuIncrements increments = ImuIncrements::kRawIntegrals;  // for kIncrements: what they contain
  bool low_rate = false;     // device documents a low output rate (UM220 GYOACC: 5-10 Hz)
  std::uint8_t saturation = 0;  // kSatGyroX.. bits: a saturated axis must not be trusted
  static constexpr std::uint32_t kValidGyro = 1u << 0;
  static constexpr std::uint32_t kValidAccel = 1u << 1;
  static constexpr std::uint8_t kSatGyroX = 1u << 0, kSatGyroY = 1u << 1, kSatGyroZ = 1u << 2;
  static constexpr std::uint8_t kSatAccelX = 1u << 3, kSatAccelY = 1u << 4, kSatAccelZ = 1u << 5;
};

struct Magnetometer {
  MeasurementHeader header;
  SensorFrame frame = SensorFrame::kSensor;
  Eigen::Vector3d field_gauss = Eigen::Vector3d::Zero();  // gauss is what every device reports
  static constexpr std::uint32_t kValidField = 1u << 0;
};

struct Pressure {
  MeasurementHeader header;
  double pressure_pa = 0.0;
  static constexpr std::uint32_t kValidPressure = 1u << 0;
};

// ---------------------------------------------------------------------------------------------
// GNSS
enum class GnssFixType : std::uint8_t {
  kNone = 0,
  kTimeOnly = 1,
  kFix2D = 2,
  kFix3D = 3,
  kDgnss = 4,
  kSbas = 5,
  kRtkFloat = 6,
  kRtkFixed = 7,
  kPpp = 8,
  kDeadReckoning = 9,  // receiver's own DR output: not a GNSS measurement, never fused as one
};

struct GnssPosition {
  MeasurementHeader header;
  double lat_rad = 0.0;
  double lon_rad = 0.0;
  double height_m = 0.0;  // above the WGS-84 ellipsoid
  Eigen::Matrix3d cov_ned_m2 = Eigen::Matrix3d::Identity();
  GnssFixType fix = GnssFixType::kNone;
  std::uint8_t num_sats = 0;
  std::uint8_t receiver_id = 0;  // 0 primary antenna, 1 secondary, ...
  static constexpr std::uint32_t kValidPosition = 1u << 0;
  static constexpr std::uint32_t kValidHeight = 1u << 1;
  static constexpr std::uint32_t kValidCovariance = 1u << 2;
};

struct GnssVelocity {
  MeasurementHeader header;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov_ned_m2ps2 = Eigen::Matrix3d::Identity();
  GnssFixType fix = GnssFixType::kNone;
  std::uint8_t receiver_id = 0;
  static constexpr std::uint32_t kValidVelocity = 1u << 0;  // all three axes
  static constexpr std::uint32_t kValidCovariance = 1u << 1;
};

// Dual-antenna (GNSS compass) solution: direction of the baseline from primary to secondary
// antenna, relative to true north, in the local level frame.
struct GnssHeading {
  MeasurementHeader header;
  double heading_rad = 0.0;  // baseline azimuth, clockwise from true north, [-pi, pi)
  double heading_std_rad = 0.0;
  double pitch_rad = 0.0;    // baseline elevation (positive up)
  double pitch_std_rad = 0.0;
  double baseline_m = 0.0;   // measured baseline length (0: not reported)
  GnssFixType fix = GnssFixType::kNone;
  static constexpr std::uint32_t kValidHeading = 1u << 0;
  static constexpr std::uint32_t kValidPitch = 1u << 1;
  static constexpr std::uint32_t kValidBaseline = 1u << 2;
};

// ---------------------------------------------------------------------------------------------
// Odometry
enum class Gear : std::uint8_t { kUnknown = 0, kForward = 1, kReverse = 2, kPark = 3, kNeutral = 4 };

struct WheelSpeeds {
  MeasurementHeader header;
  // Order: front-left, front-right, rear-left, rear-right. m/s, positive forward when is_signed.
  std::array<double, 4> speed_mps{};
  Gear gear = Gear::kUnknown;
  bool is_signed = false;  // false: magnitude only, direction from gear
  double speed_std_mps = 0.0;  // 0: use the configured wheel.speed_std_mps
  static constexpr std::uint32_t kValidFrontLeft = 1u << 0, kValidFrontRight = 1u << 1;
  static constexpr std::uint32_t kValidRearLeft = 1u << 2, kValidRearRight = 1u << 3;
};

struct VehicleSpeed {
  MeasurementHeader header;
  double speed_mps = 0.0;
  Gear gear = Gear::kUnknown;
  bool is_signed = false;
  double speed_std_mps = 0.0;  // 0: use the configured wheel.speed_std_mps
  static constexpr std::uint32_t kValidSpeed = 1u << 0;
};

// Raw tick counters (wheel encoders or a single odometer / vehicle tick). Counters roll over at
// `rollover` (0: 2^32); a tick-to-metre scale lives in configuration or the filter state.
struct WheelTicks {
  MeasurementHeader header;
  std::array<std::uint32_t, 4> ticks{};  // FL, FR, RL, RR; a single odometer uses [0] only
  std::uint8_t channels = 4;             // 1 for a vehicle-level tick counter / odometer
  std::uint64_t rollover = 0;
  Gear gear = Gear::kUnknown;
  bool is_signed = false;
  double period_s = 0.0;  // pulse period when the device reports one (UM220 GYOACC), else 0
  static constexpr std::uint32_t kValidFrontLeft = 1u << 0, kValidFrontRight = 1u << 1;
  static constexpr std::uint32_t kValidRearLeft = 1u << 2, kValidRearRight = 1u << 3;
};

// ---------------------------------------------------------------------------------------------
// External aiding. Per-axis validity and 1-sigma uncertainty, like MIP 0x13. `lever_arm_m` is
// where the aiding sensor measures, in the vehicle frame (front-ends apply any configured
// sensor-to-vehicle transform before producing these).
enum class PositionFrame : std::uint8_t { kLlh = 0, kEcef = 1 };
struct ExternalPosition {
  MeasurementHeader header;
  PositionFrame frame = PositionFrame::kLlh;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();    // LLH: lat rad, lon rad, h m; ECEF: m
  Eigen::Vector3d std_m = Eigen::Vector3d::Zero();    // LLH: north, east, down; ECEF: x, y, z
  Eigen::Vector3d lever_arm_m = Eigen::Vector3d::Zero();
  static constexpr std::uint32_t kValidX = 1u << 0, kValidY = 1u << 1, kValidZ = 1u << 2;
};

enum class VelocityFrame : std::uint8_t { kNed = 0, kEcef = 1, kVehicle = 2 };
struct ExternalVelocity {
  MeasurementHeader header;
  VelocityFrame frame = VelocityFrame::kNed;
  Eigen::Vector3d value_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d std_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d lever_arm_m = Eigen::Vector3d::Zero();
  static constexpr std::uint32_t kValidX = 1u << 0, kValidY = 1u << 1, kValidZ = 1u << 2;
};

struct ExternalHeading {
  MeasurementHeader header;
  double heading_rad = 0.0;  // vehicle x-axis azimuth from true north, clockwise
  double std_rad = 0.0;
  static constexpr std::uint32_t kValidHeading = 1u << 0;
};

// ---------------------------------------------------------------------------------------------
// A complete navigation solution: a device's own (decoded, for benchmarking) or navfuse's
// (produced by the filter, encoded by front-ends).
enum class NavMode : std::uint8_t {
  kInvalid = 0,        // nothing yet
  kInitializing = 1,   // collecting data for levelling
  kVerticalGyro = 2,   // roll/pitch known, heading not
  kAhrs = 3,           // attitude known, no position
  kNavigation = 4,     // full position/velocity/attitude with GNSS or equivalent aiding
  kDeadReckoning = 5,  // full navigation coasting on IMU (+wheel) without absolute aiding
  kSmoothed = 6,       // post-processed (navfuse smooth): the forward filter was navigating here
};
std::string_view to_string(NavMode mode);

struct NavSolution {
  MeasurementHeader header;
  NavMode mode = NavMode::kInvalid;
  GnssFixType gnss_fix = GnssFixType::kNone;  // best absolute aiding in use
  double lat_rad = 0.0, lon_rad = 0.0, height_m = 0.0;
  double undulation_m = 0.0;  // geoid height above ellipsoid; valid only with kValidUndulation
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d vel_body_mps = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_nb = Eigen::Quaterniond::Identity();  // vehicle (FRD) -> NED
  Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();         // roll, pitch, yaw (3-2-1)
  Eigen::Vector3d pos_std_ned_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d vel_std_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d att_std_rpy_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias_rps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias_std_rps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_std_mps2 = Eigen::Vector3d::Zero();
  // The other estimated calibration states (filter solutions, valid with kValidBiases), each with
  // its 1-sigma std. A state the filter does not estimate has `estimated` false, its configured
  // value and std 0.
  struct Calibration {
    struct Scalar {
      bool estimated = false;
      double value = 0.0, std = 0.0;
    };
    template <int N>
    struct Vector {
      bool estimated = false;
      Eigen::Matrix<double, N, 1> value = Eigen::Matrix<double, N, 1>::Zero();
      Eigen::Matrix<double, N, 1> std = Eigen::Matrix<double, N, 1>::Zero();
    };
    Scalar odometer_scale_error;  // measured speed = (1 + error) * true speed
    Vector<2> mount_pitch_yaw_rad;  // residual IMU-to-vehicle pitch and yaw
    Vector<3> gnss_lever_arm_m;     // primary antenna, vehicle frame: configured + estimated
    Vector<3> gyro_scale;           // measured = (1 + scale) * true, vehicle frame
    Vector<3> accel_scale;
    Scalar gnss_time_offset_s;  // residual: to add to GNSS times (after the configured offset)
  };
  Calibration calibration;
  Eigen::Vector3d angular_rate_rps = Eigen::Vector3d::Zero();   // bias-compensated, vehicle frame
  Eigen::Vector3d linear_accel_mps2 = Eigen::Vector3d::Zero();  // gravity removed, vehicle frame
  Eigen::Vector3d gravity_ned_mps2 = Eigen::Vector3d::Zero();
  std::uint32_t device_status = 0;  // raw device status word (device solutions only)
  std::uint32_t status_flags = 0;   // kStatus* bits below
  static constexpr std::uint32_t kValidPosition = 1u << 0;
  static constexpr std::uint32_t kValidVelocity = 1u << 1;
  static constexpr std::uint32_t kValidAttitude = 1u << 2;
  static constexpr std::uint32_t kValidPositionStd = 1u << 3;
  static constexpr std::uint32_t kValidVelocityStd = 1u << 4;
  static constexpr std::uint32_t kValidAttitudeStd = 1u << 5;
  static constexpr std::uint32_t kValidBiases = 1u << 6;
  static constexpr std::uint32_t kValidUndulation = 1u << 7;
  static constexpr std::uint32_t kValidHeading = 1u << 8;  // yaw meaningful (not only roll/pitch)
  static constexpr std::uint32_t kStatusGnssOutage = 1u << 0;
  static constexpr std::uint32_t kStatusStationary = 1u << 1;
  static constexpr std::uint32_t kStatusDiverged = 1u << 2;
  static constexpr std::uint32_t kStatusImuFault = 1u << 3;
  static constexpr std::uint32_t kStatusWheelAiding = 1u << 4;
  static constexpr std::uint32_t kStatusDualAntennaHeading = 1u << 5;
  // The dual-antenna heading disagreed with the course over ground while moving: the configured
  // baseline is wrong (e.g. antennas swapped); GNSS heading is no longer used.
  static constexpr std::uint32_t kStatusHeadingOffset = 1u << 6;
};

// ---------------------------------------------------------------------------------------------
// The measurement variant and its kinds. The kind names are the `measurements` keys of the
// `--summary-json` output (DESIGN.md, contract).
using Measurement =
    std::variant<ImuSample, GnssPosition, GnssVelocity, GnssHeading, WheelSpeeds, VehicleSpeed,
                 WheelTicks, ExternalPosition, ExternalVelocity, ExternalHeading, NavSolution,
                 Magnetometer, Pressure>;

enum class MeasurementKind : std::uint8_t {
  kImu = 0,
  kGnssPosition,
  kGnssVelocity,
  kGnssHeading,
  kWheelSpeed,
  kVehicleSpeed,
  kWheelTicks,
  kExternalPosition,
  kExternalVelocity,
  kExternalHeading,
  kDeviceSolution,
  kMagnetometer,
  kPressure,
  kCount,
};
static_assert(static_cast<std::size_t>(MeasurementKind::kCount) == std::variant_size_v<Measurement>,
              "one kind per variant alternative, in the same order");

inline MeasurementKind kind_of(const Measurement& m) {
  return static_cast<MeasurementKind>(m.index());
}
// "imu", "gnss_position", ... "device_solution", "magnetometer", "pressure".
std::string_view to_string(MeasurementKind kind);
std::string_view to_string(GnssFixType fix);
std::string_view to_string(TimeSource source);
const MeasurementHeader& header_of(const Measurement& m);
MeasurementHeader& header_of(Measurement& m);

}  // namespace navfuse

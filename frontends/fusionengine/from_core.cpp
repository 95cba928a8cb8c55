#include "frontends/fusionengine/from_core.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/geodesy/geoid.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

using rot::kRadToDeg;

bool has(std::uint32_t valid, std::uint32_t bit) { return (valid & bit) != 0; }

// Scaled integer with the 0x7FFFFFFF sentinel kept out of the value range.
std::int32_t to_scaled(double value, double lsb) {
  if (!std::isfinite(value)) return kInvalidI32;
  const double scaled = std::round(value / lsb);
  constexpr double kMax = static_cast<double>(kInvalidI32 - 1);
  constexpr double kMin = static_cast<double>(std::numeric_limits<std::int32_t>::min());
  return static_cast<std::int32_t>(std::clamp(scaled, kMin, kMax));
}

// Standard deviations of a NED-resolved diagonal covariance, re-resolved in the body frame:
// sqrt(diag(C_bn diag(s^2) C_nb)). Axis sign flips (FRD -> FLU) do not change them.
// Only the diagonal is formed: var_b(i) = sum_k C_bn(i, k)^2 s_k^2, C_bn's row i being C_nb's
// column i.
Eigen::Vector3d body_std_from_ned(const Eigen::Quaterniond& q_nb, const Eigen::Vector3d& std_ned) {
  const Eigen::Matrix3d c_nb = q_nb.normalized().toRotationMatrix();
  const Eigen::Vector3d var_ned = std_ned.cwiseAbs2();
  Eigen::Vector3d var_b;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d row = c_nb.col(i);
    var_b(i) = (row(0) * var_ned(0)) * row(0) + (row(1) * var_ned(1)) * row(1) + (row(2) * var_ned(2)) * row(2);
  }
  return var_b.cwiseMax(0.0).cwiseSqrt();
}

std::uint8_t gear_of(Gear g) { return static_cast<std::uint8_t>(g); }

}  // namespace

Timestamp p1_time_of(const MeasurementHeader& h) { return Timestamp::from_ns(h.time_ns); }

Timestamp gps_time_of(const MeasurementHeader& h) {
  return h.time_source == TimeSource::kGps ? Timestamp::from_ns(h.time_ns) : Timestamp{};
}

MeasurementDetails details_of(const MeasurementHeader& h, SensorDataSource source) {
  MeasurementDetails d;
  d.measurement_time = Timestamp::from_ns(h.time_ns);
  d.time_source = static_cast<std::uint8_t>(
      h.time_source == TimeSource::kGps ? SystemTimeSource::kGpsTime : SystemTimeSource::kP1Time);
  d.sensor_source = static_cast<std::uint8_t>(source);
  d.p1_time = p1_time_of(h);
  return d;
}

SolutionType solution_type_of(NavMode mode, GnssFixType fix) {
  switch (mode) {
    case NavMode::kInvalid:
    case NavMode::kInitializing:
      return SolutionType::kInvalid;
    case NavMode::kVerticalGyro:
    case NavMode::kAhrs:
      // Before the heading is known a position held at the GNSS fixes is still that fix's.
      if (fix == GnssFixType::kNone) return SolutionType::kInvalid;
      break;
    case NavMode::kDeadReckoning:
      return SolutionType::kIntegrate;
    case NavMode::kSmoothed:  // FusionEngine has no post-processed type (§4.1): the aiding in use
      if (fix == GnssFixType::kNone) return SolutionType::kIntegrate;
      break;
    case NavMode::kNavigation:
      break;
  }
  switch (fix) {
    case GnssFixType::kRtkFixed: return SolutionType::kRtkFixed;
    case GnssFixType::kRtkFloat: return SolutionType::kRtkFloat;
    case GnssFixType::kDgnss:
    case GnssFixType::kSbas: return SolutionType::kDgps;  // "... or SBAS corrections" (L1771)
    case GnssFixType::kPpp: return SolutionType::kPpp;
    default: return SolutionType::kAutonomousGps;
  }
}

PoseMessage pose_from(const NavSolution& s) {
  PoseMessage m;
  m.p1_time = p1_time_of(s.header);
  m.gps_time = gps_time_of(s.header);
  m.solution_type = static_cast<std::uint8_t>(solution_type_of(s.mode, s.gnss_fix));
  m.flags = has(s.status_flags, NavSolution::kStatusStationary) ? kPoseFlagStationary : 0;
  const std::uint32_t v = s.header.valid;

  std::optional<double> undulation_m;
  if (has(v, NavSolution::kValidUndulation)) {
    undulation_m = s.undulation_m;
  } else if (has(v, NavSolution::kValidPosition)) {
    undulation_m = geo::egm96_undulation_m(s.lat_rad, s.lon_rad);
  }
  if (undulation_m && std::isfinite(*undulation_m)) {
    m.undulation_cm = static_cast<std::int16_t>(std::clamp(std::round(*undulation_m * 100.0), -32767.0, 32767.0));
  }

  if (has(v, NavSolution::kValidPosition)) {
    m.lla_deg = {s.lat_rad * kRadToDeg, s.lon_rad * kRadToDeg, s.height_m};
  } else {
    m.lla_deg = {kNan, kNan, kNan};
  }
  if (has(v, NavSolution::kValidPositionStd)) {
    m.position_std_enu_m = {static_cast<float>(s.pos_std_ned_m.y()), static_cast<float>(s.pos_std_ned_m.x()),
                            static_cast<float>(s.pos_std_ned_m.z())};
  } else {
    m.position_std_enu_m = {kNanF, kNanF, kNanF};
  }

  const bool attitude = has(v, NavSolution::kValidAttitude);
  if (attitude) {
    const Eigen::Vector3d rpy = rot::rpy_from_quat(rot::quat_enu_flu_from_ned_frd(s.q_nb));
    // Yaw is meaningless until heading is known (vertical gyro / AHRS without heading).
    const double yaw = has(v, NavSolution::kValidHeading) ? rpy.z() * kRadToDeg : kNan;
    m.ypr_deg = {yaw, rpy.y() * kRadToDeg, rpy.x() * kRadToDeg};
  } else {
    m.ypr_deg = {kNan, kNan, kNan};
  }
  if (has(v, NavSolution::kValidAttitudeStd)) {
    m.ypr_std_deg = {static_cast<float>(s.att_std_rpy_rad.z() * kRadToDeg),
                     static_cast<float>(s.att_std_rpy_rad.y() * kRadToDeg),
                     static_cast<float>(s.att_std_rpy_rad.x() * kRadToDeg)};
  } else {
    m.ypr_std_deg = {kNanF, kNanF, kNanF};
  }

  m.velocity_body_mps = {kNan, kNan, kNan};
  m.velocity_std_body_mps = {kNanF, kNanF, kNanF};
  if (attitude && has(v, NavSolution::kValidVelocity)) {
    const Eigen::Vector3d v_flu = rot::flu_from_frd(s.q_nb.normalized().conjugate() * s.vel_ned_mps);
    m.velocity_body_mps = {v_flu.x(), v_flu.y(), v_flu.z()};
  }
  if (attitude && has(v, NavSolution::kValidVelocityStd)) {
    const Eigen::Vector3d sd = body_std_from_ned(s.q_nb, s.vel_std_ned_mps);
    m.velocity_std_body_mps = {static_cast<float>(sd.x()), static_cast<float>(sd.y()), static_cast<float>(sd.z())};
  }
  m.aggregate_protection_level_m = kNanF;
  m.horizontal_protection_level_m = kNanF;
  m.vertical_protection_level_m = kNanF;
  return m;
}

PoseAuxMessage pose_aux_from(const NavSolution& s) {
  PoseAuxMessage m;
  m.p1_time = p1_time_of(s.header);
  const std::uint32_t v = s.header.valid;
  const bool attitude = has(v, NavSolution::kValidAttitude);
  m.position_std_body_m = {kNanF, kNanF, kNanF};
  m.position_cov_enu_m2.fill(kNan);
  if (has(v, NavSolution::kValidPositionStd)) {
    const Eigen::Vector3d std_enu = rot::enu_from_ned(s.pos_std_ned_m).cwiseAbs();
    m.position_cov_enu_m2.fill(0.0);
    for (int i = 0; i < 3; ++i) m.position_cov_enu_m2[static_cast<std::size_t>(4 * i)] = std_enu[i] * std_enu[i];
    if (attitude) {
      const Eigen::Vector3d sd = body_std_from_ned(s.q_nb, s.pos_std_ned_m);
      m.position_std_body_m = {static_cast<float>(sd.x()), static_cast<float>(sd.y()), static_cast<float>(sd.z())};
    }
  }
  if (attitude) {
    const Eigen::Quaterniond q = rot::quat_enu_flu_from_ned_frd(s.q_nb).normalized();
    m.attitude_quaternion = {q.x(), q.y(), q.z(), q.w()};
  } else {
    m.attitude_quaternion = {kNan, kNan, kNan, kNan};
  }
  if (has(v, NavSolution::kValidVelocity)) {
    const Eigen::Vector3d e = rot::enu_from_ned(s.vel_ned_mps);
    m.velocity_enu_mps = {e.x(), e.y(), e.z()};
  } else {
    m.velocity_enu_mps = {kNan, kNan, kNan};
  }
  if (has(v, NavSolution::kValidVelocityStd)) {
    const Eigen::Vector3d e = rot::enu_from_ned(s.vel_std_ned_mps).cwiseAbs();
    m.velocity_std_enu_mps = {static_cast<float>(e.x()), static_cast<float>(e.y()), static_cast<float>(e.z())};
  } else {
    m.velocity_std_enu_mps = {kNanF, kNanF, kNanF};
  }
  return m;
}

GnssInfoMessage gnss_info_from(const NavSolution& s, std::uint8_t num_svs, float hdop, float vdop) {
  GnssInfoMessage m;
  m.p1_time = p1_time_of(s.header);
  m.gps_time = gps_time_of(s.header);
  if (s.header.time_source == TimeSource::kGps) {
    m.leap_second_s = static_cast<std::uint8_t>(time::gps_minus_utc_s_at_gps(s.header.time_ns));
  }
  m.num_svs = num_svs;
  m.gdop = kNanF;
  m.pdop = (std::isfinite(hdop) && std::isfinite(vdop)) ? std::sqrt(hdop * hdop + vdop * vdop) : kNanF;
  m.hdop = hdop;
  m.vdop = vdop;
  m.gps_time_std_s = kNanF;
  return m;
}

bool imu_output_from(const ImuSample& imu, ImuOutputMessage& out) {
  if (imu.frame != SensorFrame::kVehicle) return false;
  double scale = 1.0;
  if (imu.quantity == ImuQuantity::kIncrements) {
    if (!(imu.dt_s > 0.0)) return false;
    scale = 1.0 / imu.dt_s;
  }
  out = ImuOutputMessage{};
  out.p1_time = p1_time_of(imu.header);
  const Eigen::Vector3d a = rot::flu_from_frd(imu.accel * scale);
  const Eigen::Vector3d g = rot::flu_from_frd(imu.gyro * scale);
  const bool accel_ok = has(imu.header.valid, ImuSample::kValidAccel);
  const bool gyro_ok = has(imu.header.valid, ImuSample::kValidGyro);
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out.accel_mps2[k] = accel_ok ? a[i] : kNan;
    out.gyro_rps[k] = gyro_ok ? g[i] : kNan;
    out.accel_std_mps2[k] = kNan;  // no per-sample uncertainty in core ImuSample
    out.gyro_std_rps[k] = kNan;
  }
  return true;
}

bool scaled_imu_from(const ImuSample& imu, ScaledImuLayout& out) {
  double scale = 1.0;
  if (imu.quantity == ImuQuantity::kIncrements) {
    if (!(imu.dt_s > 0.0)) return false;
    scale = 1.0 / imu.dt_s;
  }
  out.details = details_of(imu.header, SensorDataSource::kInternal);
  out.temperature = kInvalidTemperature;
  const bool accel_ok = has(imu.header.valid, ImuSample::kValidAccel);
  const bool gyro_ok = has(imu.header.valid, ImuSample::kValidGyro);
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out.accel[k] = accel_ok ? to_scaled(imu.accel[i] * scale, kAccelLsbMps2) : kInvalidI32;
    out.gyro[k] = gyro_ok ? to_scaled(imu.gyro[i] * scale, kGyroLsbRps) : kInvalidI32;
  }
  return true;
}

GnssAttitudeOutputMessage gnss_attitude_from(const GnssHeading& h) {
  GnssAttitudeOutputMessage m;
  m.details = details_of(h.header, SensorDataSource::kInternal);
  const bool heading_ok = has(h.header.valid, GnssHeading::kValidHeading);
  // "Invalid: Heading not available; RTKFixed: Heading available" (L2072).
  m.solution_type = static_cast<std::uint8_t>(heading_ok ? SolutionType::kRtkFixed : SolutionType::kInvalid);
  const double yaw_deg = rot::wrap_pi(rot::kPi / 2 - h.heading_rad) * kRadToDeg;
  m.ypr_deg = {heading_ok ? static_cast<float>(yaw_deg) : kNanF,
               has(h.header.valid, GnssHeading::kValidPitch) ? static_cast<float>(-h.pitch_rad * kRadToDeg) : kNanF,
               kNanF};
  m.ypr_std_deg = {heading_ok ? static_cast<float>(h.heading_std_rad * kRadToDeg) : kNanF,
                   has(h.header.valid, GnssHeading::kValidPitch) ? static_cast<float>(h.pitch_std_rad * kRadToDeg) : kNanF,
                   kNanF};
  m.baseline_distance_m = has(h.header.valid, GnssHeading::kValidBaseline) ? static_cast<float>(h.baseline_m) : kNanF;
  m.baseline_distance_std_m = kNanF;
  return m;
}

WheelSpeedLayout wheel_speed_from(const WheelSpeeds& w) {
  WheelSpeedLayout m;
  m.details = details_of(w.header, SensorDataSource::kUnknown);
  for (std::size_t i = 0; i < 4; ++i) {
    m.speed[i] = has(w.header.valid, 1u << i) ? to_scaled(w.speed_mps[i], kWheelSpeedLsbMps) : kInvalidI32;
  }
  m.gear = gear_of(w.gear);
  m.flags = w.is_signed ? kSpeedFlagSigned : 0;
  return m;
}

VehicleSpeedLayout vehicle_speed_from(const VehicleSpeed& v) {
  VehicleSpeedLayout m;
  m.details = details_of(v.header, SensorDataSource::kUnknown);
  m.speed = has(v.header.valid, VehicleSpeed::kValidSpeed) ? to_scaled(v.speed_mps, kWheelSpeedLsbMps) : kInvalidI32;
  m.gear = gear_of(v.gear);
  m.flags = v.is_signed ? kSpeedFlagSigned : 0;
  return m;
}

WheelTickLayout wheel_ticks_from(const WheelTicks& t) {
  WheelTickLayout m;
  m.details = details_of(t.header, SensorDataSource::kUnknown);
  m.ticks = t.ticks;
  m.gear = gear_of(t.gear);
  return m;
}

VehicleTickLayout vehicle_ticks_from(const WheelTicks& t) {
  VehicleTickLayout m;
  m.details = details_of(t.header, SensorDataSource::kUnknown);
  m.ticks = t.ticks[0];
  m.gear = gear_of(t.gear);
  return m;
}

WheelSpeedOutputMessage wheel_speed_output_from(const WheelSpeeds& w) {
  WheelSpeedOutputMessage m;
  m.p1_time = p1_time_of(w.header);
  m.gear = gear_of(w.gear);
  m.flags = w.is_signed ? kSpeedFlagSigned : 0;
  for (std::size_t i = 0; i < 4; ++i) {
    m.speed_mps[i] = has(w.header.valid, 1u << i) ? static_cast<float>(w.speed_mps[i]) : kNanF;
  }
  return m;
}

VehicleSpeedOutputMessage vehicle_speed_output_from(const VehicleSpeed& v) {
  VehicleSpeedOutputMessage m;
  m.p1_time = p1_time_of(v.header);
  m.gear = gear_of(v.gear);
  m.flags = v.is_signed ? kSpeedFlagSigned : 0;
  m.speed_mps = has(v.header.valid, VehicleSpeed::kValidSpeed) ? static_cast<float>(v.speed_mps) : kNanF;
  return m;
}

namespace {
RosGpsFixMessage empty_fix(const MeasurementHeader& h) {
  RosGpsFixMessage m;
  m.p1_time = p1_time_of(h);
  // f64 seconds since 1980-01-06 (digest §13 A12); resolves ~0.25 us at today's GPS times.
  m.gps_time_s = h.time_source == TimeSource::kGps ? static_cast<double>(h.time_ns) * 1e-9 : kNan;
  for (double* d : {&m.latitude_deg, &m.longitude_deg, &m.altitude_m, &m.track_deg, &m.speed_mps,
                    &m.climb_mps, &m.pitch_deg, &m.roll_deg, &m.dip_deg, &m.gdop, &m.pdop, &m.hdop,
                    &m.vdop, &m.tdop, &m.err_3d_m, &m.err_horizontal_m, &m.err_vertical_m,
                    &m.err_track_deg, &m.err_speed_mps, &m.err_climb_mps, &m.err_time_s,
                    &m.err_pitch_deg, &m.err_roll_deg, &m.err_dip_deg}) {
    *d = kNan;
  }
  m.position_covariance_m2.fill(kNan);
  m.position_covariance_type = static_cast<std::uint8_t>(CovarianceType::kUnknown);
  return m;
}
}  // namespace

RosGpsFixMessage gps_fix_from(const GnssPosition& p) {
  RosGpsFixMessage m = empty_fix(p.header);
  if (has(p.header.valid, GnssPosition::kValidPosition)) {
    m.latitude_deg = p.lat_rad * kRadToDeg;
    m.longitude_deg = p.lon_rad * kRadToDeg;
  }
  if (has(p.header.valid, GnssPosition::kValidHeight)) m.altitude_m = p.height_m;
  if (has(p.header.valid, GnssPosition::kValidCovariance)) {
    // ENU = T * NED with T the axis swap; P_enu = T P_ned T^T.
    Eigen::Matrix3d t;
    t << 0, 1, 0, 1, 0, 0, 0, 0, -1;
    const Eigen::Matrix3d enu = t * p.cov_ned_m2 * t.transpose();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m.position_covariance_m2[static_cast<std::size_t>(3 * r + c)] = enu(r, c);
    m.position_covariance_type = static_cast<std::uint8_t>(CovarianceType::kKnown);
    m.err_horizontal_m = std::sqrt(std::max(0.0, enu(0, 0) + enu(1, 1)));
    m.err_vertical_m = std::sqrt(std::max(0.0, enu(2, 2)));
    m.err_3d_m = std::sqrt(std::max(0.0, enu.trace()));
  }
  return m;
}

RosGpsFixMessage gps_fix_from(const GnssVelocity& v) {
  RosGpsFixMessage m = empty_fix(v.header);
  if (!has(v.header.valid, GnssVelocity::kValidVelocity)) return m;
  const double vn = v.vel_ned_mps.x(), ve = v.vel_ned_mps.y();
  const double speed = std::hypot(vn, ve);
  const double track = std::atan2(ve, vn);
  m.speed_mps = speed;
  m.track_deg = rot::wrap_two_pi(track) * kRadToDeg;
  m.climb_mps = -v.vel_ned_mps.z();
  if (has(v.header.valid, GnssVelocity::kValidCovariance)) {
    // Along-track and cross-track variances of the horizontal covariance; the cross-track one
    // becomes a track-angle error (rad = m/s / speed). Below 1 mm/s the track is undefined.
    const Eigen::Matrix2d h = v.cov_ned_m2ps2.topLeftCorner<2, 2>();
    const Eigen::Vector2d along(std::cos(track), std::sin(track));
    const Eigen::Vector2d cross(-std::sin(track), std::cos(track));
    m.err_speed_mps = std::sqrt(std::max(0.0, along.dot(h * along)));
    const double cross_std = std::sqrt(std::max(0.0, cross.dot(h * cross)));
    m.err_track_deg = speed > kMinTrackSpeedMps ? (cross_std / speed) * kRadToDeg : kNan;
    m.err_climb_mps = std::sqrt(std::max(0.0, v.cov_ned_m2ps2(2, 2)));
  }
  return m;
}

}  // namespace navfuse::frontends::fusionengine

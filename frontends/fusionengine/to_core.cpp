#include "frontends/fusionengine/to_core.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

using rot::kDegToRad;

bool finite3(const auto& a) { return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]); }

Gear gear_of(std::uint8_t wire) {
  return wire <= static_cast<std::uint8_t>(GearType::kNeutral) ? static_cast<Gear>(wire) : Gear::kUnknown;
}

// NED standard deviations of a body-resolved diagonal covariance (the inverse of the encoder's
// re-resolution; exact for the diagonal, the cross terms are dropped).
Eigen::Vector3d ned_std_from_body(const Eigen::Quaterniond& q_nb, const Eigen::Vector3d& std_body) {
  const Eigen::Matrix3d c_nb = q_nb.normalized().toRotationMatrix();
  const Eigen::Matrix3d cov = c_nb * std_body.cwiseAbs2().asDiagonal() * c_nb.transpose();
  return cov.diagonal().cwiseMax(0.0).cwiseSqrt();
}

// ENU <-> NED axis swap as a matrix, for covariances: P_ned = T P_enu T^T (T is its own inverse).
Eigen::Matrix3d enu_ned_swap() {
  Eigen::Matrix3d t;
  t << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  return t;
}

}  // namespace

NavMode nav_mode_of(SolutionType type) {
  switch (type) {
    case SolutionType::kInvalid: return NavMode::kInvalid;
    case SolutionType::kIntegrate: return NavMode::kDeadReckoning;
    default: return NavMode::kNavigation;
  }
}

GnssFixType gnss_fix_of(SolutionType type) {
  switch (type) {
    case SolutionType::kAutonomousGps: return GnssFixType::kFix3D;
    case SolutionType::kDgps: return GnssFixType::kDgnss;
    case SolutionType::kRtkFixed: return GnssFixType::kRtkFixed;
    case SolutionType::kRtkFloat: return GnssFixType::kRtkFloat;
    case SolutionType::kPpp: return GnssFixType::kPpp;
    default: return GnssFixType::kNone;  // invalid, integrate, visual, reserved
  }
}

NavSolution solution_from(const PoseMessage& pose) {
  NavSolution s;
  const auto type = static_cast<SolutionType>(pose.solution_type);
  s.mode = nav_mode_of(type);
  s.gnss_fix = gnss_fix_of(type);
  s.device_status = static_cast<std::uint32_t>(pose.solution_type) | static_cast<std::uint32_t>(pose.flags) << 8;
  if ((pose.flags & kPoseFlagStationary) != 0) s.status_flags |= NavSolution::kStatusStationary;
  std::uint32_t valid = 0;

  // "Invalid, no position available" (L1770): coordinates of an invalid solution are not used.
  if (type != SolutionType::kInvalid && finite3(pose.lla_deg)) {
    s.lat_rad = pose.lla_deg[0] * kDegToRad;
    s.lon_rad = pose.lla_deg[1] * kDegToRad;
    s.height_m = pose.lla_deg[2];
    valid |= NavSolution::kValidPosition;
  }
  if (pose.undulation_cm != kInvalidUndulationCm) {
    s.undulation_m = pose.undulation_cm * 0.01;
    valid |= NavSolution::kValidUndulation;
  }
  if (finite3(pose.position_std_enu_m)) {
    s.pos_std_ned_m = {pose.position_std_enu_m[1], pose.position_std_enu_m[0], pose.position_std_enu_m[2]};
    valid |= NavSolution::kValidPositionStd;
  }

  const double yaw_deg = pose.ypr_deg[0], pitch_deg = pose.ypr_deg[1], roll_deg = pose.ypr_deg[2];
  if (std::isfinite(pitch_deg) && std::isfinite(roll_deg)) {
    const bool heading = std::isfinite(yaw_deg);
    const Eigen::Quaterniond q_enu_flu = rot::quat_from_rpy(
        Eigen::Vector3d(roll_deg, pitch_deg, heading ? yaw_deg : 0.0) * kDegToRad);
    s.q_nb = rot::quat_ned_frd_from_enu_flu(q_enu_flu).normalized();
    s.rpy_rad = rot::rpy_from_quat(s.q_nb);
    valid |= NavSolution::kValidAttitude | (heading ? NavSolution::kValidHeading : 0u);
  }
  if (finite3(pose.ypr_std_deg)) {
    s.att_std_rpy_rad = Eigen::Vector3d(pose.ypr_std_deg[2], pose.ypr_std_deg[1], pose.ypr_std_deg[0]) * kDegToRad;
    valid |= NavSolution::kValidAttitudeStd;
  }
  if ((valid & NavSolution::kValidAttitude) != 0 && finite3(pose.velocity_body_mps)) {
    s.vel_body_mps = rot::frd_from_flu({pose.velocity_body_mps[0], pose.velocity_body_mps[1], pose.velocity_body_mps[2]});
    s.vel_ned_mps = s.q_nb * s.vel_body_mps;
    valid |= NavSolution::kValidVelocity;
    if (finite3(pose.velocity_std_body_mps)) {
      s.vel_std_ned_mps = ned_std_from_body(
          s.q_nb, {pose.velocity_std_body_mps[0], pose.velocity_std_body_mps[1], pose.velocity_std_body_mps[2]});
      valid |= NavSolution::kValidVelocityStd;
    }
  }
  s.header.valid = valid;
  return s;
}

// ---------------------------------------------------------------------------------------------
// Time

void MeasurementMapper::learn_offset(const Timestamp& p1, const Timestamp& gps) {
  if (p1.valid() && gps.valid()) gps_minus_p1_ns_ = gps.ns() - p1.ns();
}

MeasurementHeader MeasurementMapper::header_from_p1(const Timestamp& p1) const {
  MeasurementHeader h;
  if (!p1.valid()) return h;  // kUnknown, time 0
  if (gps_minus_p1_ns_) {
    h.time_ns = p1.ns() + *gps_minus_p1_ns_;
    h.time_source = TimeSource::kGps;
  } else {
    h.time_ns = p1.ns();
    h.time_source = TimeSource::kDeviceMonotonic;
  }
  return h;
}

MeasurementHeader MeasurementMapper::header_from_details(const MeasurementDetails& d) {
  const auto source = static_cast<SystemTimeSource>(d.time_source);
  if (source == SystemTimeSource::kGpsTime && d.measurement_time.valid()) {
    learn_offset(d.p1_time, d.measurement_time);
    return {d.measurement_time.ns(), TimeSource::kGps, 0, 0};
  }
  if (source == SystemTimeSource::kP1Time && d.measurement_time.valid()) return header_from_p1(d.measurement_time);
  if (source == SystemTimeSource::kSenderSystemTime && d.measurement_time.valid()) {
    return {d.measurement_time.ns(), TimeSource::kDeviceMonotonic, 0, 0};
  }
  // Invalid / timestamped on reception: the device's computed P1 time, when it filled it in.
  return header_from_p1(d.p1_time);
}

void MeasurementMapper::close_epoch_unless(const Timestamp& p1, Sink& sink) {
  if (!pending_) return;
  if (p1.valid() && p1.seconds == pending_p1_.seconds && p1.fraction_ns == pending_p1_.fraction_ns) return;
  flush(sink);
}

void MeasurementMapper::flush(Sink& sink) {
  if (!pending_) return;
  const Measurement m = *pending_;
  pending_.reset();
  sink.on_measurement(m);
}

// ---------------------------------------------------------------------------------------------
// Device solution: Pose + PoseAux + GNSSInfo of one epoch

void MeasurementMapper::on(const PoseMessage& m, Sink& sink) {
  flush(sink);
  learn_offset(m.p1_time, m.gps_time);
  NavSolution s = solution_from(m);
  const std::uint32_t valid = s.header.valid;
  if (m.gps_time.valid()) {
    s.header = {m.gps_time.ns(), TimeSource::kGps, 0, 0};
  } else {
    s.header = header_from_p1(m.p1_time);
  }
  s.header.valid = valid;
  pending_ = s;
  pending_p1_ = m.p1_time;
}

void MeasurementMapper::on(const PoseAuxMessage& m, Sink& sink) {
  close_epoch_unless(m.p1_time, sink);
  if (!pending_) return;  // PoseAux completes a Pose; alone it is not a solution
  NavSolution& s = *pending_;
  if ((s.header.valid & NavSolution::kValidAttitude) == 0 && std::isfinite(m.attitude_quaternion[3]) &&
      finite3(m.attitude_quaternion)) {
    const Eigen::Quaterniond q(m.attitude_quaternion[3], m.attitude_quaternion[0], m.attitude_quaternion[1],
                               m.attitude_quaternion[2]);
    if (q.norm() > 0.5) {
      s.q_nb = rot::quat_ned_frd_from_enu_flu(q.normalized()).normalized();
      s.rpy_rad = rot::rpy_from_quat(s.q_nb);
      s.header.valid |= NavSolution::kValidAttitude | NavSolution::kValidHeading;
    }
  }
  if (finite3(m.velocity_enu_mps)) {
    s.vel_ned_mps = rot::ned_from_enu({m.velocity_enu_mps[0], m.velocity_enu_mps[1], m.velocity_enu_mps[2]});
    if ((s.header.valid & NavSolution::kValidAttitude) != 0) s.vel_body_mps = s.q_nb.conjugate() * s.vel_ned_mps;
    s.header.valid |= NavSolution::kValidVelocity;
  }
  if (finite3(m.velocity_std_enu_mps)) {
    s.vel_std_ned_mps = {m.velocity_std_enu_mps[1], m.velocity_std_enu_mps[0], m.velocity_std_enu_mps[2]};
    s.header.valid |= NavSolution::kValidVelocityStd;
  }
}

void MeasurementMapper::on(const GnssInfoMessage& m, Sink& sink) {
  close_epoch_unless(m.p1_time, sink);
  learn_offset(m.p1_time, m.gps_time);
  if (pending_ && pending_->header.time_source != TimeSource::kGps && m.gps_time.valid()) {
    const std::uint32_t valid = pending_->header.valid;
    pending_->header = {m.gps_time.ns(), TimeSource::kGps, 0, valid};
  }
}

// ---------------------------------------------------------------------------------------------
// IMU

void MeasurementMapper::on(const ImuOutputMessage& m, Sink& sink) {
  close_epoch_unless(m.p1_time, sink);
  ImuSample s;
  s.header = header_from_p1(m.p1_time);
  s.quantity = ImuQuantity::kRates;
  s.frame = SensorFrame::kVehicle;  // "rotated into the vehicle body frame" (L2039)
  if (finite3(m.gyro_rps)) {
    s.gyro = rot::frd_from_flu({m.gyro_rps[0], m.gyro_rps[1], m.gyro_rps[2]});
    s.header.valid |= ImuSample::kValidGyro;
  }
  if (finite3(m.accel_mps2)) {
    s.accel = rot::frd_from_flu({m.accel_mps2[0], m.accel_mps2[1], m.accel_mps2[2]});
    s.header.valid |= ImuSample::kValidAccel;
  }
  sink.on_measurement(s);
}

void MeasurementMapper::on(const ScaledImuLayout& m, Sink& sink) {
  close_epoch_unless(m.details.p1_time, sink);
  ImuSample s;
  s.header = header_from_details(m.details);
  s.quantity = ImuQuantity::kRates;
  s.frame = SensorFrame::kSensor;  // "resolved in the sensor measurement frame" (L2313, B16)
  const auto axis_ok = [](const std::array<std::int32_t, 3>& a) {
    return a[0] != kInvalidI32 && a[1] != kInvalidI32 && a[2] != kInvalidI32;
  };
  if (axis_ok(m.gyro)) {
    s.gyro = Eigen::Vector3d(m.gyro[0], m.gyro[1], m.gyro[2]) * kGyroLsbRps;
    s.header.valid |= ImuSample::kValidGyro;
  }
  if (axis_ok(m.accel)) {
    s.accel = Eigen::Vector3d(m.accel[0], m.accel[1], m.accel[2]) * kAccelLsbMps2;
    s.header.valid |= ImuSample::kValidAccel;
  }
  sink.on_measurement(s);
}

// ---------------------------------------------------------------------------------------------
// Dual-antenna attitude

void MeasurementMapper::on(const GnssAttitudeOutputMessage& m, Sink& sink) {
  close_epoch_unless(m.details.p1_time, sink);
  GnssHeading h;
  h.header = header_from_details(m.details);
  const bool available = static_cast<SolutionType>(m.solution_type) != SolutionType::kInvalid;
  h.fix = available ? GnssFixType::kRtkFixed : GnssFixType::kNone;
  // Heading from north = 90 deg - ENU yaw (spec §2.7 L648).
  if (available && std::isfinite(m.ypr_deg[0])) {
    h.heading_rad = rot::wrap_pi(rot::kPi / 2 - m.ypr_deg[0] * kDegToRad);
    h.heading_std_rad = m.ypr_std_deg[0] * kDegToRad;
    h.header.valid |= GnssHeading::kValidHeading;
  }
  // FusionEngine pitch is positive nose down (L643); core baseline pitch is positive up.
  if (available && std::isfinite(m.ypr_deg[1])) {
    h.pitch_rad = -m.ypr_deg[1] * kDegToRad;
    h.pitch_std_rad = m.ypr_std_deg[1] * kDegToRad;
    h.header.valid |= GnssHeading::kValidPitch;
  }
  if (std::isfinite(m.baseline_distance_m)) {
    h.baseline_m = m.baseline_distance_m;
    h.header.valid |= GnssHeading::kValidBaseline;
  }
  sink.on_measurement(h);
}

void MeasurementMapper::on(const RawGnssAttitudeOutputMessage& m, Sink& sink) {
  close_epoch_unless(m.details.p1_time, sink);
  GnssHeading h;
  h.header = header_from_details(m.details);
  const bool available = static_cast<SolutionType>(m.solution_type) != SolutionType::kInvalid;
  h.fix = available ? GnssFixType::kRtkFixed : GnssFixType::kNone;
  const double e = m.relative_position_enu_m[0], n = m.relative_position_enu_m[1], u = m.relative_position_enu_m[2];
  const double horiz = std::hypot(e, n);
  if (available && finite3(m.relative_position_enu_m) && horiz > 0.0) {
    // Baseline azimuth and elevation of the ENU vector (digest §6.3) with first-order stds.
    const double se = m.position_std_enu_m[0], sn = m.position_std_enu_m[1], su = m.position_std_enu_m[2];
    const double len2 = horiz * horiz + u * u;
    h.heading_rad = std::atan2(e, n);
    h.pitch_rad = std::atan2(u, horiz);
    h.baseline_m = std::sqrt(len2);
    h.header.valid |= GnssHeading::kValidHeading | GnssHeading::kValidPitch | GnssHeading::kValidBaseline;
    if (finite3(m.position_std_enu_m)) {
      h.heading_std_rad = std::sqrt(n * n * se * se + e * e * sn * sn) / (horiz * horiz);
      const double s_horiz = std::sqrt(e * e * se * se + n * n * sn * sn) / horiz;
      h.pitch_std_rad = std::sqrt(horiz * horiz * su * su + u * u * s_horiz * s_horiz) / len2;
    }
  }
  sink.on_measurement(h);
}

// ---------------------------------------------------------------------------------------------
// Wheels and vehicle speed

void MeasurementMapper::tick_rollover(WheelTicks& t, bool single_channel) const {
  // Rollover per WheelConfig (L1134-1160): unsigned counters span [0, max]; signed ones span
  // [-(max + 1), max] ("asymmetric, consistent with a typical 2's complement rollover") and are
  // mapped onto [0, 2 (max + 1)) so that differences modulo the rollover stay right.
  const std::uint64_t max = wheel_config_.wheel_tick_max_value;
  if (!wheel_config_known_ || max == 0) return;  // rollover 0 = 2^32
  const bool is_signed = wheel_config_.wheel_ticks_signed != 0;
  const std::uint64_t range = is_signed ? 2 * (max + 1) : max + 1;
  t.rollover = range;
  const std::size_t n = single_channel ? 1 : 4;
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t value =
        is_signed ? static_cast<std::int64_t>(static_cast<std::int32_t>(t.ticks[i])) : static_cast<std::int64_t>(t.ticks[i]);
    const auto r = static_cast<std::int64_t>(range);
    t.ticks[i] = static_cast<std::uint32_t>(((value % r) + r) % r);
  }
  // Ticks that decrease when driving backward carry direction (L1160).
  t.is_signed = wheel_config_.wheel_ticks_always_increase == 0;
}

void MeasurementMapper::on(const WheelTickLayout& m, Sink& sink) {
  close_epoch_unless(m.details.p1_time, sink);
  WheelTicks t;
  t.header = header_from_details(m.details);
  t.ticks = m.ticks;
  t.channels = 4;
  t.gear = gear_of(m.gear);
  t.header.valid = WheelTicks::kValidFrontLeft | WheelTicks::kValidFrontRight | WheelTicks::kValidRearLeft |
                   WheelTicks::kValidRearRight;
  tick_rollover(t, false);
  sink.on_measurement(t);
}

void MeasurementMapper::on(const VehicleTickLayout& m, Sink& sink) {
  close_epoch_unless(m.details.p1_time, sink);
  WheelTicks t;
  t.header = header_from_details(m.details);
  t.ticks = {m.ticks, 0, 0, 0};
  t.channels = 1;
  t.gear = gear_of(m.gear);
  t.header.valid = WheelTicks::kValidFrontLeft;
  tick_rollover(t, true);
  sink.on_measurement(t);
}

void MeasurementMapper::on(const WheelSpeedLayout& m, Sink& sink) {
  close_epoch_unless(m.details.p1_time, sink);
  WheelSpeeds w;
  w.header = header_from_details(m.details);
  for (std::size_t i = 0; i < 4; ++i) {
    if (m.speed[i] == kInvalidI32) continue;
    w.speed_mps[i] = m.speed[i] * kWheelSpeedLsbMps;
    w.header.valid |= 1u << i;  // kValidFrontLeft .. kValidRearRight in wire order
  }
  w.gear = gear_of(m.gear);
  w.is_signed = (m.flags & kSpeedFlagSigned) != 0;
  sink.on_measurement(w);
}

void MeasurementMapper::on(const VehicleSpeedLayout& m, Sink& sink) {
  close_epoch_unless(m.details.p1_time, sink);
  VehicleSpeed v;
  v.header = header_from_details(m.details);
  if (m.speed != kInvalidI32) {
    v.speed_mps = m.speed * kWheelSpeedLsbMps;
    v.header.valid |= VehicleSpeed::kValidSpeed;
  }
  v.gear = gear_of(m.gear);
  v.is_signed = (m.flags & kSpeedFlagSigned) != 0;
  sink.on_measurement(v);
}

void MeasurementMapper::on(const WheelSpeedOutputMessage& m, Sink& sink) {
  close_epoch_unless(m.p1_time, sink);
  WheelSpeeds w;
  w.header = header_from_p1(m.p1_time);
  for (std::size_t i = 0; i < 4; ++i) {
    if (!std::isfinite(m.speed_mps[i])) continue;  // "NAN if unavailable" (L2111-2114)
    w.speed_mps[i] = m.speed_mps[i];
    w.header.valid |= 1u << i;
  }
  w.gear = gear_of(m.gear);
  w.is_signed = (m.flags & kSpeedFlagSigned) != 0;
  sink.on_measurement(w);
}

void MeasurementMapper::on(const VehicleSpeedOutputMessage& m, Sink& sink) {
  close_epoch_unless(m.p1_time, sink);
  VehicleSpeed v;
  v.header = header_from_p1(m.p1_time);
  if (std::isfinite(m.speed_mps)) {
    v.speed_mps = m.speed_mps;
    v.header.valid |= VehicleSpeed::kValidSpeed;
  }
  v.gear = gear_of(m.gear);
  v.is_signed = (m.flags & kSpeedFlagSigned) != 0;
  sink.on_measurement(v);
}

// ---------------------------------------------------------------------------------------------
// GNSS fixes carried in ROSGPSFix (see from_core.hpp)

void MeasurementMapper::on(const RosGpsFixMessage& m, Sink& sink) {
  close_epoch_unless(m.p1_time, sink);
  MeasurementHeader header;
  if (std::isfinite(m.gps_time_s) && m.gps_time_s > 0.0) {
    // f64 seconds resolve ~0.25 us at current GPS times: round to whole microseconds.
    header = {std::llround(m.gps_time_s * 1e6) * 1000, TimeSource::kGps, 0, 0};
  } else {
    header = header_from_p1(m.p1_time);
  }
  const Eigen::Matrix3d t = enu_ned_swap();
  if (std::isfinite(m.latitude_deg) && std::isfinite(m.longitude_deg)) {
    GnssPosition p;
    p.header = header;
    p.lat_rad = m.latitude_deg * kDegToRad;
    p.lon_rad = m.longitude_deg * kDegToRad;
    p.fix = GnssFixType::kFix3D;  // the message carries no fix type
    p.header.valid |= GnssPosition::kValidPosition;
    if (std::isfinite(m.altitude_m)) {
      p.height_m = m.altitude_m;
      p.header.valid |= GnssPosition::kValidHeight;
    }
    Eigen::Matrix3d enu;
    bool finite = true;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        enu(r, c) = m.position_covariance_m2[static_cast<std::size_t>(3 * r + c)];
        finite = finite && std::isfinite(enu(r, c));
      }
    }
    if (finite && static_cast<CovarianceType>(m.position_covariance_type) != CovarianceType::kUnknown) {
      p.cov_ned_m2 = t * enu * t.transpose();
      p.header.valid |= GnssPosition::kValidCovariance;
    }
    sink.on_measurement(p);
  }
  if (std::isfinite(m.track_deg) && std::isfinite(m.speed_mps) && std::isfinite(m.climb_mps)) {
    GnssVelocity v;
    v.header = header;
    v.fix = GnssFixType::kFix3D;
    const double track = m.track_deg * kDegToRad;
    v.vel_ned_mps = {m.speed_mps * std::cos(track), m.speed_mps * std::sin(track), -m.climb_mps};
    v.header.valid |= GnssVelocity::kValidVelocity;
    if (std::isfinite(m.err_speed_mps) && std::isfinite(m.err_climb_mps)) {
      const double along = m.err_speed_mps;
      const double cross = std::isfinite(m.err_track_deg) ? m.speed_mps * m.err_track_deg * kDegToRad : along;
      Eigen::Matrix2d r;
      r << std::cos(track), -std::sin(track), std::sin(track), std::cos(track);
      const Eigen::Matrix2d h = r * Eigen::Vector2d(along * along, cross * cross).asDiagonal() * r.transpose();
      v.cov_ned_m2ps2.setZero();
      v.cov_ned_m2ps2.topLeftCorner<2, 2>() = h;
      v.cov_ned_m2ps2(2, 2) = m.err_climb_mps * m.err_climb_mps;
      v.header.valid |= GnssVelocity::kValidCovariance;
    }
    sink.on_measurement(v);
  }
}

// ---------------------------------------------------------------------------------------------
// Wheel configuration seen in the stream

void MeasurementMapper::apply_config(std::uint16_t config_type, const std::vector<std::uint8_t>& value) {
  if (config_type != to_u16(ConfigType::kWheelConfig)) return;
  if (auto c = parse_config<WheelConfig>(value)) {
    wheel_config_ = *c;
    wheel_config_known_ = true;
  }
}

void MeasurementMapper::on(const SetConfigMessage& m, Sink&) { apply_config(m.config_type, m.value); }

void MeasurementMapper::on(const ConfigResponseMessage& m, Sink&) {
  if (m.response == static_cast<std::uint8_t>(Response::kOk)) apply_config(m.config_type, m.value);
}

}  // namespace navfuse::frontends::fusionengine

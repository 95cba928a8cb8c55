#include "frontends/vectornav/to_core.hpp"

#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/vectornav/group_gnss.hpp"
#include "frontends/vectornav/group_imu.hpp"
#include "frontends/vectornav/ins_status.hpp"

namespace navfuse::frontends::vectornav {
namespace {

using rot::kDegToRad;

// A rate sample's nominal period is taken from the spacing of consecutive samples when it is
// plausible (VN binary output runs at 400/RateDivisor Hz, L5221: at least 1 Hz in practice).
constexpr std::int64_t kMaxRatePeriodNs = time::kNsPerSecond;

Eigen::Vector3d vec(const Vec3f& v) { return {v[0], v[1], v[2]}; }
Eigen::Vector3d vec(const Vec3d& v) { return {v[0], v[1], v[2]}; }

std::optional<std::int64_t> plausible_ns(std::uint64_t ns) {
  if (ns == 0 || ns > kMaxPlausibleTimeNs) return std::nullopt;
  return static_cast<std::int64_t>(ns);
}

// GPS time of week + week as carried by the Time and GNSS groups (both in ns and weeks).
std::optional<std::int64_t> gps_from_week_tow(std::uint16_t week, std::uint64_t tow_ns) {
  if (week == 0 || week > kMaxPlausibleGpsWeek || tow_ns >= static_cast<std::uint64_t>(time::kNsPerWeek))
    return std::nullopt;
  return time::gps_ns_from_week_tow_ns(week, static_cast<std::int64_t>(tow_ns));
}

geo::Llh llh_deg(const Vec3d& lla) { return {lla[0] * kDegToRad, lla[1] * kDegToRad, lla[2]}; }

}  // namespace

std::optional<GnssFixType> fix_from_vn(std::uint8_t fix) {
  switch (fix) {
    case vn_fix::kNoFix: return GnssFixType::kNone;
    case vn_fix::kTimeOnly: return GnssFixType::kTimeOnly;
    case vn_fix::kFix2D: return GnssFixType::kFix2D;
    case vn_fix::kFix3D: return GnssFixType::kFix3D;
    case vn_fix::kSbas: return GnssFixType::kSbas;
    case vn_fix::kRtkFloat: return GnssFixType::kRtkFloat;
    case vn_fix::kRtkFix: return GnssFixType::kRtkFixed;
    default: return std::nullopt;
  }
}

std::uint8_t vn_from_fix(GnssFixType fix) {
  switch (fix) {
    case GnssFixType::kNone:
    case GnssFixType::kDeadReckoning: return vn_fix::kNoFix;
    case GnssFixType::kTimeOnly: return vn_fix::kTimeOnly;
    case GnssFixType::kFix2D: return vn_fix::kFix2D;
    case GnssFixType::kFix3D:
    case GnssFixType::kPpp: return vn_fix::kFix3D;
    case GnssFixType::kDgnss:
    case GnssFixType::kSbas: return vn_fix::kSbas;
    case GnssFixType::kRtkFloat: return vn_fix::kRtkFloat;
    case GnssFixType::kRtkFixed: return vn_fix::kRtkFix;
  }
  return vn_fix::kNoFix;
}

Stamp BinaryMapper::message_stamp(const BinaryMessage& m) {
  // TimeStatus bit 0 (TowValid, Table 2.15) gates the GPS time when the message carries it.
  const bool status_known = m.has(kSlotTime, time_type::kTimeStatus);
  const bool tow_valid = !status_known || (m.time.time_status & kTimeStatusTowValid) != 0;
  std::optional<std::int64_t> gps;
  if (tow_valid) {
    if (m.has_either(kSlotTime, time_type::kTimeGps, common_type::kTimeGps)) {
      gps = plausible_ns(m.time.time_gps_ns);
    } else if (m.has(kSlotTime, time_type::kGpsTow) && m.has(kSlotTime, time_type::kGpsWeek)) {
      gps = gps_from_week_tow(m.time.gps_week, m.time.gps_tow_ns);
    }
  }
  std::optional<std::int64_t> startup;
  if (m.has_either(kSlotTime, time_type::kTimeStartup, common_type::kTimeStartup) &&
      m.time.time_startup_ns <= kMaxPlausibleTimeNs)
    startup = static_cast<std::int64_t>(m.time.time_startup_ns);
  if (!gps && !startup) return clock_.latest();
  return clock_.resolve(gps, startup);
}

int BinaryMapper::map(const BinaryMessage& m, DecodeSink& sink) {
  const Stamp stamp = message_stamp(m);
  int problems = map_imu(m, stamp, sink);
  for (std::size_t r = 0; r < kGnssReceivers; ++r)
    if (m.header.types[kGnssSlots[r]] != 0) problems += map_gnss(m, r, stamp, sink);
  problems += map_solution(m, stamp, sink);
  return problems;
}

int BinaryMapper::map_imu(const BinaryMessage& m, const Stamp& stamp, DecodeSink& sink) {
  const ImuFields& f = m.imu;
  const bool theta = m.has_either(kSlotImu, imu_type::kDeltaTheta, common_type::kDeltas);
  const bool dvel = m.has_either(kSlotImu, imu_type::kDeltaVel, common_type::kDeltas);
  const bool ugyro = m.has_either(kSlotImu, imu_type::kUncompGyro, common_type::kImu);
  const bool uaccel = m.has_either(kSlotImu, imu_type::kUncompAccel, common_type::kImu);
  const bool cgyro = m.has_either(kSlotImu, imu_type::kAngularRate, common_type::kAngularRate);
  const bool caccel = m.has_either(kSlotImu, imu_type::kAccel, common_type::kAccel);

  ImuSample s;
  s.header.time_ns = stamp.time_ns;
  s.header.time_source = stamp.source;
  s.frame = options_.imu_frame;
  if (theta || dvel) {
    // Every poll or scheduled output resets both integrals (L1054, L1066), so each message's
    // increments cover exactly its own DeltaTime, ending at the message time; nothing is
    // accumulated across messages. A delta-velocity without DeltaTheta has no interval.
    s.quantity = ImuQuantity::kIncrements;
    // Coning- and sculling-integrated on board at 800 Hz (ICD 2.4.7-2.4.8).
    s.increments = ImuIncrements::kCompensated;
    if (theta && !(std::isfinite(f.delta_time_s) && f.delta_time_s > 0.0f)) return 1;
    s.dt_s = theta ? f.delta_time_s : 0.0;
    if (theta) {
      s.gyro = vec(f.delta_theta_deg) * kDegToRad;  // DeltaTheta is in degrees (L1054)
      s.header.valid |= ImuSample::kValidGyro;
    }
    if (dvel) {
      s.accel = vec(f.delta_vel_mps);
      s.header.valid |= ImuSample::kValidAccel;
    }
  } else if (ugyro || uaccel || cgyro || caccel) {
    s.quantity = ImuQuantity::kRates;
    if (ugyro || cgyro) {
      s.gyro = vec(ugyro ? f.uncomp_gyro_rps : f.angular_rate_rps);
      s.header.valid |= ImuSample::kValidGyro;
    }
    if (uaccel || caccel) {
      s.accel = vec(uaccel ? f.uncomp_accel_mps2 : f.accel_mps2);
      s.header.valid |= ImuSample::kValidAccel;
    }
    if (last_rate_time_ns_ && stamp.time_ns > *last_rate_time_ns_ &&
        stamp.time_ns - *last_rate_time_ns_ <= kMaxRatePeriodNs)
      s.dt_s = time::seconds(stamp.time_ns - *last_rate_time_ns_);
    last_rate_time_ns_ = stamp.time_ns;
  } else {
    return 0;
  }
  // Saturation per axis from SensSat (Table 2.34); without it, ImuStatus' 2-bit states
  // (Table 2.18) flag all three axes of a saturated sensor. Failed sensors are invalid.
  if (m.has(kSlotImu, imu_type::kSensSat)) {
    const auto accel = static_cast<std::uint8_t>((f.sens_sat >> kSensSatAccelShift) & 0x7u);
    const auto gyro = static_cast<std::uint8_t>((f.sens_sat >> kSensSatGyroShift) & 0x7u);
    s.saturation = static_cast<std::uint8_t>(gyro | (accel << 3));
  }
  if (m.has(kSlotImu, imu_type::kImuStatus)) {
    const unsigned gyro_state = (f.imu_status >> kImuStatusGyroShift) & kImuStatusFieldMask;
    const unsigned accel_state = (f.imu_status >> kImuStatusAccelShift) & kImuStatusFieldMask;
    if (!m.has(kSlotImu, imu_type::kSensSat)) {
      if (gyro_state == kImuStateSaturated)
        s.saturation |= ImuSample::kSatGyroX | ImuSample::kSatGyroY | ImuSample::kSatGyroZ;
      if (accel_state == kImuStateSaturated)
        s.saturation |= ImuSample::kSatAccelX | ImuSample::kSatAccelY | ImuSample::kSatAccelZ;
    }
    if (gyro_state == kImuStateFailed) s.header.valid &= ~ImuSample::kValidGyro;
    if (accel_state == kImuStateFailed) s.header.valid &= ~ImuSample::kValidAccel;
  }
  sink.on_measurement(s);
  return 0;
}

int BinaryMapper::map_gnss(const BinaryMessage& m, std::size_t receiver, const Stamp& message, DecodeSink& sink) {
  const std::size_t slot = kGnssSlots[receiver];
  const GnssFields& g = m.gnss[receiver];
  int problems = 0;
  std::optional<GnssFixType> fix;
  if (m.has(slot, gnss_type::kGnssFix)) {
    fix = fix_from_vn(g.fix);
    if (!fix) ++problems;  // 5 and 6 are undefined (Table 2.41)
  }
  // The group's own GPS time is the fix time; the message time only if it has none.
  Stamp stamp = message;
  const bool tow = m.has(slot, gnss_type::kGpsTow);
  const bool tow_valid = !m.has(slot, gnss_type::kTimeInfo) || (g.time_status & kTimeStatusTowValid) != 0;
  if (tow && m.has(slot, gnss_type::kGpsWeek) && tow_valid) {
    if (const auto gps = gps_from_week_tow(g.gps_week, g.gps_tow_ns)) {
      stamp = {*gps, TimeSource::kGps};
    }
  }
  const bool lla = m.has(slot, gnss_type::kPosLla);
  const bool ecef = m.has(slot, gnss_type::kPosEcef);
  geo::Llh pos;
  if (lla) pos = llh_deg(g.pos_lla);
  else if (ecef) pos = geo::llh_from_ecef(vec(g.pos_ecef_m));
  const GnssFixType fix_value = fix.value_or(GnssFixType::kNone);
  const bool usable = !fix || fix_value >= GnssFixType::kFix2D;

  if ((lla || ecef) && !(tow && last_position_tow_[receiver] == g.gps_tow_ns)) {
    if (tow) last_position_tow_[receiver] = g.gps_tow_ns;
    GnssPosition p;
    p.header.time_ns = stamp.time_ns;
    p.header.time_source = stamp.source;
    p.lat_rad = pos.lat_rad;
    p.lon_rad = pos.lon_rad;
    p.height_m = pos.height_m;
    p.fix = fix_value;
    p.receiver_id = static_cast<std::uint8_t>(receiver);
    if (m.has(slot, gnss_type::kNumSats)) p.num_sats = g.num_sats;
    if (usable) {
      p.header.valid |= GnssPosition::kValidPosition;
      if (!fix || fix_value != GnssFixType::kFix2D) p.header.valid |= GnssPosition::kValidHeight;
    }
    if (m.has(slot, gnss_type::kPosUncertainty)) {
      // The ICD does not state the sigma level (Table 2.35); taken as 1 sigma like YprU/PosU.
      const Eigen::Vector3d u = vec(g.pos_uncertainty_ned_m);
      p.cov_ned_m2 = u.cwiseProduct(u).asDiagonal();
      p.header.valid |= GnssPosition::kValidCovariance;
    }
    sink.on_measurement(p);
  }

  const bool vned = m.has(slot, gnss_type::kVelNed);
  const bool vecef = m.has(slot, gnss_type::kVelEcef) && (lla || ecef);
  if ((vned || vecef) && !(tow && last_velocity_tow_[receiver] == g.gps_tow_ns)) {
    if (tow) last_velocity_tow_[receiver] = g.gps_tow_ns;
    GnssVelocity v;
    v.header.time_ns = stamp.time_ns;
    v.header.time_source = stamp.source;
    v.vel_ned_mps = vned ? vec(g.vel_ned_mps)
                         : Eigen::Vector3d(geo::rot_ecef_from_ned(pos.lat_rad, pos.lon_rad).transpose() *
                                           vec(g.vel_ecef_mps));
    v.fix = fix_value;
    v.receiver_id = static_cast<std::uint8_t>(receiver);
    if (usable) v.header.valid |= GnssVelocity::kValidVelocity;
    if (m.has(slot, gnss_type::kVelUncertainty)) {
      const double u = g.vel_uncertainty_mps;  // scalar, applied to each axis
      v.cov_ned_m2ps2 = Eigen::Matrix3d::Identity() * (u * u);
      v.header.valid |= GnssVelocity::kValidCovariance;
    }
    sink.on_measurement(v);
  }
  return problems;
}

int BinaryMapper::map_solution(const BinaryMessage& m, const Stamp& stamp, DecodeSink& sink) {
  const bool status = m.has_either(kSlotIns, ins_type::kInsStatus, common_type::kInsStatus);
  const bool lla = m.has_either(kSlotIns, ins_type::kPosLla, common_type::kPosLla);
  const bool ecef = m.has(kSlotIns, ins_type::kPosEcef);
  const bool vned = m.has_either(kSlotIns, ins_type::kVelNed, common_type::kVelNed);
  const bool vecef = m.has(kSlotIns, ins_type::kVelEcef);
  const bool vbody = m.has(kSlotIns, ins_type::kVelBody);
  const bool quat = m.has_either(kSlotAttitude, attitude_type::kQuaternion, common_type::kQuaternion);
  const bool ypr = m.has_either(kSlotAttitude, attitude_type::kYpr, common_type::kYpr);
  const bool dcm = m.has(kSlotAttitude, attitude_type::kDcm);
  if (!(status || lla || ecef || vned || vecef || vbody || quat || ypr || dcm)) return 0;

  const InsFields& ins = m.ins;
  const AttitudeFields& att = m.attitude;
  NavSolution s;
  s.header.time_ns = stamp.time_ns;
  s.header.time_source = stamp.source;

  // Attitude: quaternion (scalar last, L1540-1550; it is q_nb up to sign, checked against the
  // Reg 8/Reg 9 examples), else Ypr (3-2-1, deg), else the DCM (errata A9: row k/3, column k%3 of
  // C_body<-NED).
  const bool attitude = quat || ypr || dcm;
  if (quat) {
    s.q_nb = Eigen::Quaterniond(att.quaternion[3], att.quaternion[0], att.quaternion[1], att.quaternion[2]);
    if (s.q_nb.norm() > 0) s.q_nb.normalize();
  }
  if (ypr) {
    s.rpy_rad = Eigen::Vector3d(att.ypr_deg[2], att.ypr_deg[1], att.ypr_deg[0]) * kDegToRad;
    if (!quat) s.q_nb = rot::quat_from_rpy(s.rpy_rad);
  } else if (quat) {
    s.rpy_rad = rot::rpy_from_quat(s.q_nb);
  } else if (dcm) {
    Eigen::Matrix3d c_bn;
    for (int k = 0; k < 9; ++k) c_bn(k / 3, k % 3) = att.dcm[static_cast<std::size_t>(k)];
    s.q_nb = Eigen::Quaterniond(Eigen::Matrix3d(c_bn.transpose()));
    s.q_nb.normalize();
    s.rpy_rad = rot::rpy_from_quat(s.q_nb);
  }
  const bool attitude_nonzero = (quat || ypr || dcm) && (s.rpy_rad.cwiseAbs().maxCoeff() > 0.0 ||
                                                         (quat && std::abs(att.quaternion[3]) < 1.0f));

  InsValidity valid{true, true};
  if (status) {
    const InsStatus st = decode_ins_status(ins.ins_status);
    s.device_status = ins.ins_status;
    s.mode = nav_mode_of(st, attitude_nonzero);
    s.status_flags = status_flags_of(st);
    s.gnss_fix = st.gnss_fix ? GnssFixType::kFix3D : GnssFixType::kNone;
    valid = validity_of(st.mode);
    // Mode 0 attitude comes from the AHRS when it is aiding (L1700): usable attitude.
    if (st.mode == InsMode::kNotTracking && attitude_nonzero) valid.attitude = true;
  } else {
    s.mode = (lla || ecef) ? NavMode::kNavigation : NavMode::kAhrs;
  }

  geo::Llh pos;
  if (lla) pos = llh_deg(ins.pos_lla);
  else if (ecef) pos = geo::llh_from_ecef(vec(ins.pos_ecef_m));
  if (lla || ecef) {
    s.lat_rad = pos.lat_rad;
    s.lon_rad = pos.lon_rad;
    s.height_m = pos.height_m;
    if (valid.position_velocity) s.header.valid |= NavSolution::kValidPosition;
  }
  if (vned || (vecef && (lla || ecef))) {
    s.vel_ned_mps = vned ? vec(ins.vel_ned_mps)
                         : Eigen::Vector3d(geo::rot_ecef_from_ned(pos.lat_rad, pos.lon_rad).transpose() *
                                           vec(ins.vel_ecef_mps));
    if (valid.position_velocity) s.header.valid |= NavSolution::kValidVelocity;
  }
  if (vbody) s.vel_body_mps = vec(ins.vel_body_mps);
  if (attitude && valid.attitude) s.header.valid |= NavSolution::kValidAttitude | NavSolution::kValidHeading;

  // Uncertainties are 1 sigma (L1617, L1810-1820). PosU and VelU are scalars: each axis gets it.
  if (m.has(kSlotIns, ins_type::kPosU) && (s.header.valid & NavSolution::kValidPosition)) {
    s.pos_std_ned_m.setConstant(ins.pos_uncertainty_m);
    s.header.valid |= NavSolution::kValidPositionStd;
  }
  if (m.has(kSlotIns, ins_type::kVelU) && (s.header.valid & NavSolution::kValidVelocity)) {
    s.vel_std_ned_mps.setConstant(ins.vel_uncertainty_mps);
    s.header.valid |= NavSolution::kValidVelocityStd;
  }
  if (s.header.valid & NavSolution::kValidAttitude) {
    if (m.has(kSlotAttitude, attitude_type::kYprU)) {
      s.att_std_rpy_rad = Eigen::Vector3d(att.ypr_uncertainty_deg[2], att.ypr_uncertainty_deg[1],
                                          att.ypr_uncertainty_deg[0]) * kDegToRad;
      s.header.valid |= NavSolution::kValidAttitudeStd;
    } else if (m.has(kSlotAttitude, attitude_type::kAttU)) {
      s.att_std_rpy_rad.setConstant(att.att_uncertainty_deg * kDegToRad);
      s.header.valid |= NavSolution::kValidAttitudeStd;
    }
  }
  if (m.has_either(kSlotImu, imu_type::kAngularRate, common_type::kAngularRate))
    s.angular_rate_rps = vec(m.imu.angular_rate_rps);
  if (m.has(kSlotAttitude, attitude_type::kLinBodyAcc)) s.linear_accel_mps2 = vec(att.lin_body_acc_mps2);
  sink.on_measurement(s);
  return 0;
}

}  // namespace navfuse::frontends::vectornav

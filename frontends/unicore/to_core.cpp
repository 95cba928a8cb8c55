#include "frontends/unicore/to_core.hpp"

#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::frontends::unicore {
namespace {

constexpr double kMsToS = 1e-3;
constexpr double kSqrtHalf = 0.70710678118654752440;
constexpr int kStatusByteBits = 8;

Eigen::Vector3d vec(const std::array<std::optional<Real>, 3>& a) {
  return {a[0]->value, a[1]->value, a[2]->value};
}
Eigen::Vector3d vec(const std::array<Real, 3>& a) { return {a[0].value, a[1].value, a[2].value}; }

Eigen::Matrix3d horizontal_cov(double rms_2d) {
  const double h = rms_2d * kSqrtHalf;
  const double v = rms_2d * kVerticalStdPerHorizontalRms;
  return Eigen::Vector3d(h * h, h * h, v * v).asDiagonal();
}

}  // namespace

std::uint32_t pack_snrstat(const Snrstat& s) {
  const auto byte = [](std::int32_t v) { return static_cast<std::uint32_t>(static_cast<std::uint8_t>(v)); };
  return byte(s.ins_status) | byte(s.odo_status) << kStatusByteBits |
         byte(s.install_state) << (2 * kStatusByteBits) |
         byte(s.map_status.value_or(0)) << (3 * kStatusByteBits);
}

Snrstat unpack_snrstat(std::uint32_t d) {
  const auto field = [&](int i) {
    return static_cast<std::int32_t>(static_cast<std::int8_t>((d >> (i * kStatusByteBits)) & 0xFF));
  };
  return {field(0), field(1), field(2), field(3)};
}

Eigen::Vector3d frd_from_rfu(const Eigen::Vector3d& v) { return {v.y(), v.x(), -v.z()}; }
Eigen::Vector3d rfu_from_frd(const Eigen::Vector3d& v) { return {v.y(), v.x(), -v.z()}; }

std::optional<ImuSample> imu_from_gyoacc(const Gyoacc& m, std::int64_t gps_ns) {
  for (std::size_t i = 0; i < 3; ++i) {
    if (!m.gyro_rps[i] || !m.accel_mps2[i]) return std::nullopt;
  }
  ImuSample s;
  s.header.time_ns = gps_ns;
  s.header.time_source = TimeSource::kGps;
  s.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
  // The spec does not say whether the values are instantaneous or averaged over the period
  // (digest §11 item 13): they are passed on as rates with the period as the nominal dt.
  s.quantity = ImuQuantity::kRates;
  s.low_rate = true;  // 5 Hz (10 Hz from R3.4.0.0), L371
  s.dt_s = m.gyro_period_ms * kMsToS;
  if (m.vehicle_frame) {
    s.frame = SensorFrame::kVehicle;
    s.gyro = frd_from_rfu(vec(m.gyro_rps));
    s.accel = frd_from_rfu(vec(m.accel_mps2));
  } else {
    s.frame = SensorFrame::kSensor;
    s.gyro = vec(m.gyro_rps);
    s.accel = vec(m.accel_mps2);
  }
  return s;
}

GnssFixType fix_from_quality(std::uint32_t quality) {
  switch (quality) {
    case 3: return GnssFixType::kFix3D;  // "precise"
    case 2: return GnssFixType::kFix2D;  // "coarse"
    default: return GnssFixType::kNone;  // invalid / externally configured (AIDPOS)
  }
}

std::uint32_t quality_from_fix(GnssFixType fix) {
  switch (fix) {
    case GnssFixType::kNone:
    case GnssFixType::kTimeOnly:
    case GnssFixType::kDeadReckoning: return 0;
    case GnssFixType::kFix2D: return 2;
    default: return 3;
  }
}

GnssPosition position_from_navpos(const Navpos& m, std::int64_t gps_ns, const Navacc* accuracy) {
  GnssPosition p;
  p.header.time_ns = gps_ns;
  p.header.time_source = TimeSource::kGps;
  p.lat_rad = m.lat_deg.value * rot::kDegToRad;
  p.lon_rad = m.lon_deg.value * rot::kDegToRad;
  p.height_m = m.height_m.value;  // "ellipsoid height" (L1294)
  p.fix = fix_from_quality(m.quality);
  p.header.valid = GnssPosition::kValidPosition | GnssPosition::kValidHeight;
  if (accuracy != nullptr && accuracy->pos_acc_mm > 0) {
    p.cov_ned_m2 = horizontal_cov(accuracy->pos_acc_mm * kMillimetre);
    p.header.valid |= GnssPosition::kValidCovariance;
  }
  return p;
}

GnssVelocity velocity_from_navvel(const Navvel& m, std::int64_t gps_ns, double lat_rad,
                                  double lon_rad, const Navacc* accuracy) {
  GnssVelocity v;
  v.header.time_ns = gps_ns;
  v.header.time_source = TimeSource::kGps;
  v.vel_ned_mps = geo::rot_ecef_from_ned(lat_rad, lon_rad).transpose() * vec(m.vel_ecef_mps);
  v.fix = fix_from_quality(m.quality);
  v.header.valid = GnssVelocity::kValidVelocity;
  if (accuracy != nullptr && accuracy->vel_acc_mmps > 0) {
    v.cov_ned_m2ps2 = horizontal_cov(accuracy->vel_acc_mmps * kMillimetre);
    v.header.valid |= GnssVelocity::kValidCovariance;
  }
  return v;
}

NavMode mode_from_gga_quality(std::uint32_t quality, const Snrstat* status) {
  switch (quality) {
    case 1:
    case 2: return NavMode::kNavigation;
    case 6: return NavMode::kDeadReckoning;  // "INS positioning" (L882)
    default: break;
  }
  // No position: SNRSTAT insstatus 1/2 means the INS is still initialising (L815).
  if (status != nullptr && (status->ins_status == 1 || status->ins_status == 2)) {
    return NavMode::kInitializing;
  }
  return NavMode::kInvalid;
}

std::uint32_t gga_quality_from_solution(const NavSolution& s) {
  if (!(s.header.valid & NavSolution::kValidPosition)) return 0;
  switch (s.mode) {
    case NavMode::kDeadReckoning: return 6;
    case NavMode::kNavigation:
    case NavMode::kSmoothed:
      return (s.gnss_fix == GnssFixType::kDgnss || s.gnss_fix == GnssFixType::kRtkFloat ||
              s.gnss_fix == GnssFixType::kRtkFixed)
                 ? 2
                 : 1;
    default: return 0;
  }
}

NavSolution solution_from_gga(const nmea::Gga& m, std::int64_t gps_ns, const nmea::Gst* std_dev,
                              const Snrstat* status) {
  NavSolution s;
  s.header.time_ns = gps_ns;
  s.header.time_source = TimeSource::kGps;
  s.mode = mode_from_gga_quality(m.quality, status);
  s.gnss_fix = m.quality == 2 ? GnssFixType::kDgnss
                              : (m.quality == 1 ? GnssFixType::kFix3D : GnssFixType::kNone);
  if (m.quality == 6) s.status_flags |= NavSolution::kStatusGnssOutage;
  if (status != nullptr) {
    s.device_status = pack_snrstat(*status);
    if (status->odo_status >= 2) s.status_flags |= NavSolution::kStatusWheelAiding;
    if (status->ins_status < 0) s.status_flags |= NavSolution::kStatusImuFault;
  }
  if (m.quality != 0 && m.lat && m.lon && m.height_m) {
    s.lat_rad = m.lat->deg * rot::kDegToRad;
    s.lon_rad = m.lon->deg * rot::kDegToRad;
    // msl + Altref is the ellipsoidal height whichever CFGGEOID model is set (L885-L887,
    // digest §11 item 18): with the default model the field already is the ellipsoidal height.
    const double separation = m.geoid_separation_m ? m.geoid_separation_m->value : 0.0;
    s.height_m = m.height_m->value + separation;
    s.header.valid |= NavSolution::kValidPosition;
    if (m.geoid_separation_m) {
      s.undulation_m = separation;
      s.header.valid |= NavSolution::kValidUndulation;
    }
    if (std_dev != nullptr && std_dev->std_lat_m && std_dev->std_lon_m && std_dev->std_alt_m) {
      s.pos_std_ned_m = {std_dev->std_lat_m->value, std_dev->std_lon_m->value, std_dev->std_alt_m->value};
      s.header.valid |= NavSolution::kValidPositionStd;
    }
  }
  return s;
}

NavSolution solution_from_navatt(const Navatt& m, std::int64_t gps_ns, std::optional<NavMode> mode,
                                 const Snrstat* status) {
  NavSolution s;
  s.header.time_ns = gps_ns;
  s.header.time_source = TimeSource::kGps;
  const bool level = (m.quality & kNavattRollValid) && (m.quality & kNavattPitchValid);
  const bool heading = (m.quality & kNavattYawValid) != 0;
  if (mode) {
    s.mode = *mode;
  } else {
    s.mode = level ? (heading ? NavMode::kAhrs : NavMode::kVerticalGyro) : NavMode::kInvalid;
  }
  if (status != nullptr) s.device_status = pack_snrstat(*status);
  if (level) {
    // Frame, rotation order and yaw sense are not defined by the spec (digest §11 item 29):
    // read as aerospace roll/pitch/yaw of the vehicle, yaw clockwise from north (0-360, L1383).
    s.rpy_rad = Eigen::Vector3d(m.roll_e5deg, m.pitch_e5deg, m.yaw_e5deg) * kNavattDegPerUnit * rot::kDegToRad;
    s.rpy_rad.z() = rot::wrap_pi(s.rpy_rad.z());
    s.q_nb = rot::quat_from_rpy(s.rpy_rad);
    s.att_std_rpy_rad = Eigen::Vector3d(m.roll_std_e5deg, m.pitch_std_e5deg, m.yaw_std_e5deg) *
                        kNavattDegPerUnit * rot::kDegToRad;
    s.header.valid |= NavSolution::kValidAttitude | NavSolution::kValidAttitudeStd;
    if (heading) s.header.valid |= NavSolution::kValidHeading;
  }
  return s;
}

}  // namespace navfuse::frontends::unicore

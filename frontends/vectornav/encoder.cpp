#include "frontends/vectornav/encoder.hpp"

#include <cmath>
#include <cstdio>

#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/vectornav/ascii_registers.hpp"
#include "frontends/vectornav/binary_codec.hpp"
#include "frontends/vectornav/float_cast.hpp"
#include "frontends/vectornav/group_imu.hpp"
#include "frontends/vectornav/ins_status.hpp"
#include "frontends/vectornav/to_core.hpp"

namespace navfuse::frontends::vectornav {
namespace {

using rot::kRadToDeg;

float f32(double v) { return to_f32(v); }
Vec3f f3(const Eigen::Vector3d& v) { return {f32(v.x()), f32(v.y()), f32(v.z())}; }

std::uint16_t imu_state(bool valid, bool saturated) {
  if (!valid) return kImuStateFailed;
  return saturated ? kImuStateSaturated : kImuStateNominalUpdated;
}

void append_text(const std::string& s, std::vector<std::uint8_t>& out) { out.insert(out.end(), s.begin(), s.end()); }

constexpr std::uint8_t kTimeStatusAllValid = kTimeStatusTowValid | kTimeStatusDateValid | kTimeStatusUtcValid;
constexpr int kCompassReadyPercent = 100;

}  // namespace

bool VnMeasurementEncoder::encode(const Measurement& m, std::vector<std::uint8_t>& out) {
  return std::visit(
      [&](const auto& x) -> bool {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, ImuSample>) return encode_imu(x, out);
        else if constexpr (std::is_same_v<T, NavSolution>) return encode_solution(x, out);
        else if constexpr (std::is_same_v<T, GnssPosition>) return encode_gnss_position(x, out);
        else if constexpr (std::is_same_v<T, GnssVelocity>) return encode_gnss_velocity(x, out);
        else if constexpr (std::is_same_v<T, GnssHeading>) return encode_heading(x, out);
        else if constexpr (std::is_same_v<T, VehicleSpeed>) return encode_speed(x, out);
        else return false;
      },
      m);
}

bool VnMeasurementEncoder::begin_timed(const MeasurementHeader& h) {
  msg_.header = {};
  if (h.time_ns < 0) return false;
  if (!first_time_ns_) first_time_ns_ = h.time_ns;
  msg_.header.set(kSlotTime, time_type::kTimeStartup);
  msg_.header.set(kSlotTime, time_type::kTimeGps);
  msg_.header.set(kSlotTime, time_type::kTimeStatus);
  if (h.time_source == TimeSource::kGps) {
    // TimeStartup runs on the device clock, here ideal: GPS time since the first measurement.
    const std::int64_t startup = h.time_ns - *first_time_ns_ + options_.startup_at_first_ns;
    if (startup < 0) return false;
    msg_.time.time_startup_ns = static_cast<std::uint64_t>(startup);
    msg_.time.time_gps_ns = static_cast<std::uint64_t>(h.time_ns);
    msg_.time.time_status = kTimeStatusAllValid;
  } else {
    // No GPS time yet: TimeStatus says so and the decoder falls back on TimeStartup.
    msg_.time.time_startup_ns = static_cast<std::uint64_t>(h.time_ns);
    msg_.time.time_gps_ns = 0;
    msg_.time.time_status = 0;
  }
  return true;
}

bool VnMeasurementEncoder::finish(std::vector<std::uint8_t>& out) {
  return append_binary_message(msg_, out, split_id_++);
}

bool VnMeasurementEncoder::encode_imu(const ImuSample& s, std::vector<std::uint8_t>& out) {
  if (!begin_timed(s.header)) return false;
  ImuFields& f = msg_.imu;
  const bool gyro_ok = (s.header.valid & ImuSample::kValidGyro) != 0;
  const bool accel_ok = (s.header.valid & ImuSample::kValidAccel) != 0;
  const unsigned gyro_sat = s.saturation & 0x7u;
  const unsigned accel_sat = (s.saturation >> 3) & 0x7u;
  f.imu_status = static_cast<std::uint16_t>((imu_state(gyro_ok, gyro_sat != 0) << kImuStatusGyroShift) |
                                            (imu_state(accel_ok, accel_sat != 0) << kImuStatusAccelShift));
  f.sens_sat = static_cast<std::uint16_t>((gyro_sat << kSensSatGyroShift) | (accel_sat << kSensSatAccelShift));
  msg_.header.set(kSlotImu, imu_type::kImuStatus);
  msg_.header.set(kSlotImu, imu_type::kSensSat);
  if (s.quantity == ImuQuantity::kIncrements) {
    f.delta_time_s = f32(s.dt_s);
    f.delta_theta_deg = f3(s.gyro * kRadToDeg);  // the wire unit is degrees (L1054)
    f.delta_vel_mps = f3(s.accel);
    msg_.header.set(kSlotImu, imu_type::kDeltaTheta);
    msg_.header.set(kSlotImu, imu_type::kDeltaVel);
  } else {
    f.uncomp_accel_mps2 = f3(s.accel);
    f.uncomp_gyro_rps = f3(s.gyro);
    msg_.header.set(kSlotImu, imu_type::kUncompAccel);
    msg_.header.set(kSlotImu, imu_type::kUncompGyro);
  }
  return finish(out);
}

bool VnMeasurementEncoder::encode_solution(const NavSolution& s, std::vector<std::uint8_t>& out) {
  if (!begin_timed(s.header)) return false;
  AttitudeFields& a = msg_.attitude;
  InsFields& i = msg_.ins;
  const Eigen::Vector3d ypr_deg(s.rpy_rad.z() * kRadToDeg, s.rpy_rad.y() * kRadToDeg, s.rpy_rad.x() * kRadToDeg);
  a.ypr_deg = f3(ypr_deg);
  a.quaternion = {f32(s.q_nb.x()), f32(s.q_nb.y()), f32(s.q_nb.z()), f32(s.q_nb.w())};  // scalar last
  a.ypr_uncertainty_deg = f3(Eigen::Vector3d(s.att_std_rpy_rad.z(), s.att_std_rpy_rad.y(), s.att_std_rpy_rad.x()) *
                             kRadToDeg);
  i.ins_status = encode_ins_status(ins_status_of(s));
  i.pos_lla = {s.lat_rad * kRadToDeg, s.lon_rad * kRadToDeg, s.height_m};
  i.vel_body_mps = f3(s.vel_body_mps);
  i.vel_ned_mps = f3(s.vel_ned_mps);
  // PosU / VelU are scalars: the largest axis sigma, so the device never looks better than m.
  i.pos_uncertainty_m = f32(s.pos_std_ned_m.maxCoeff());
  i.vel_uncertainty_mps = f32(s.vel_std_ned_mps.maxCoeff());
  for (unsigned t : {attitude_type::kYpr, attitude_type::kQuaternion, attitude_type::kYprU})
    msg_.header.set(kSlotAttitude, t);
  for (unsigned t : {ins_type::kInsStatus, ins_type::kPosLla, ins_type::kVelBody, ins_type::kVelNed, ins_type::kPosU,
                     ins_type::kVelU})
    msg_.header.set(kSlotIns, t);
  return finish(out);
}

bool VnMeasurementEncoder::set_gnss_time(std::size_t receiver, const MeasurementHeader& h) {
  if (h.time_ns < 0) return false;
  const std::size_t slot = kGnssSlots[receiver];
  GnssFields& g = msg_.gnss[receiver];
  const std::int64_t week = h.time_ns / time::kNsPerWeek;
  g.gps_week = static_cast<std::uint16_t>(week);
  g.gps_tow_ns = static_cast<std::uint64_t>(h.time_ns - week * time::kNsPerWeek);
  g.time_status = h.time_source == TimeSource::kGps ? kTimeStatusAllValid : 0;
  g.leap_seconds = static_cast<std::int8_t>(time::gps_minus_utc_s_at_gps(h.time_ns));
  for (unsigned t : {gnss_type::kGpsTow, gnss_type::kGpsWeek, gnss_type::kTimeInfo}) msg_.header.set(slot, t);
  return week <= 0xFFFF;
}

bool VnMeasurementEncoder::encode_gnss_position(const GnssPosition& p, std::vector<std::uint8_t>& out) {
  if (p.receiver_id >= kGnssReceivers) return false;
  msg_.header = {};
  if (!set_gnss_time(p.receiver_id, p.header)) return false;
  const std::size_t slot = kGnssSlots[p.receiver_id];
  GnssFields& g = msg_.gnss[p.receiver_id];
  g.num_sats = p.num_sats;
  g.fix = vn_from_fix(p.fix);
  g.pos_lla = {p.lat_rad * kRadToDeg, p.lon_rad * kRadToDeg, p.height_m};
  g.pos_uncertainty_ned_m = f3(p.cov_ned_m2.diagonal().cwiseMax(0.0).cwiseSqrt());
  for (unsigned t : {gnss_type::kNumSats, gnss_type::kGnssFix, gnss_type::kPosLla, gnss_type::kPosUncertainty})
    msg_.header.set(slot, t);
  return finish(out);
}

bool VnMeasurementEncoder::encode_gnss_velocity(const GnssVelocity& v, std::vector<std::uint8_t>& out) {
  if (v.receiver_id >= kGnssReceivers) return false;
  msg_.header = {};
  if (!set_gnss_time(v.receiver_id, v.header)) return false;
  const std::size_t slot = kGnssSlots[v.receiver_id];
  GnssFields& g = msg_.gnss[v.receiver_id];
  g.fix = vn_from_fix(v.fix);
  g.vel_ned_mps = f3(v.vel_ned_mps);
  g.vel_uncertainty_mps = f32(std::sqrt(std::max(0.0, v.cov_ned_m2ps2.diagonal().maxCoeff())));
  for (unsigned t : {gnss_type::kGnssFix, gnss_type::kVelNed, gnss_type::kVelUncertainty}) msg_.header.set(slot, t);
  return finish(out);
}

bool VnMeasurementEncoder::encode_heading(const GnssHeading& h, std::vector<std::uint8_t>& out) {
  if (!std::isfinite(h.heading_rad)) return false;
  const int percent = (h.header.valid & GnssHeading::kValidHeading) ? kCompassReadyPercent : 0;
  char body[64];
  std::snprintf(body, sizeof body, "VNRRG,%d,%d,%+08.3f", reg::kCompassStartup, percent,
                rot::wrap_pi(h.heading_rad) * kRadToDeg);
  append_text(make_sentence(body, options_.ascii_checksum), out);
  return true;
}

bool VnMeasurementEncoder::encode_speed(const VehicleSpeed& s, std::vector<std::uint8_t>& out) {
  if (!std::isfinite(s.speed_mps) || std::abs(s.speed_mps) > 1e6) return false;
  char body[64];
  std::snprintf(body, sizeof body, "VNWRG,%d,%.4f,0,0", reg::kVelAidMeasurement, std::abs(s.speed_mps));
  append_text(make_sentence(body, options_.ascii_checksum), out);
  return true;
}

}  // namespace navfuse::frontends::vectornav

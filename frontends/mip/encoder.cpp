#include "frontends/mip/encoder.hpp"

#include <cmath>

#include "core/geodesy/geoid.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/mip/aiding.hpp"
#include "frontends/mip/encoder_solution.hpp"
#include "frontends/mip/gnss_fix.hpp"
#include "frontends/mip/protocol.hpp"
#include "frontends/mip/time_fields.hpp"
#include "frontends/mip/units.hpp"
#include "frontends/mip/writer.hpp"

namespace navfuse::frontends::mip {
namespace {

// 0x13 descriptors and the frame used for a lever arm (digest §5.2-§5.3).
constexpr std::uint8_t kAidFrameConfig = 0x01;
constexpr std::uint8_t kAidPosEcef = 0x21, kAidPosLlh = 0x22, kAidVelEcef = 0x28, kAidVelNed = 0x29,
                       kAidVelBody = 0x2A, kAidHeading = 0x31;
constexpr std::uint8_t kLeverArmFrame = 1;
constexpr std::uint8_t kFormatEuler = 1;
constexpr std::uint8_t kTimeReserved = 0x01;  // "Reserved, set to 0x01" (digest §5.1, [EXT-SDK])
constexpr std::uint16_t kOdometerConfigured = 1;
constexpr std::uint16_t kDaStatusBothReceivers = 0x3;  // rcv_1_data_valid | rcv_2_data_valid (L4679)

void vec3f(bytes::BeWriter& w, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(v[i]));
}

std::uint8_t gnss_set(std::uint8_t receiver_id) {
  switch (receiver_id) {
    case 1: return set::kGnss2;
    case 2: return set::kGnssExternal;
    default: return set::kGnss1;
  }
}

void write_fix(PacketWriter& pw, GnssFixType fix, std::uint8_t num_sats) {
  const MipFix f = fix_to_mip(fix);
  auto& w = pw.field(gnss::kFixInfo);
  w.u8(f.fix_type);
  w.u8(num_sats);
  w.u16(f.fix_flags);
  w.u16(gnss::kFixValidType | gnss::kFixValidNumSv | gnss::kFixValidFlags);
}

bool encode_imu(const ImuSample& m, std::vector<std::uint8_t>& out) {
  PacketWriter pw(out, set::kSensor);
  write_time_fields(m.header, pw);
  if (m.dt_s > 0.0) pw.field(shared::kReferenceTimeDelta).u64(static_cast<std::uint64_t>(time::nanoseconds(m.dt_s)));
  if (m.quantity == ImuQuantity::kIncrements) {
    vec3f(pw.field(sensor::kDeltaTheta), m.gyro);
    vec3f(pw.field(sensor::kDeltaVelocity), m.accel / kGravity_mps2);  // m/s -> g*s
  } else {
    if (m.header.valid & ImuSample::kValidAccel) vec3f(pw.field(sensor::kScaledAccel), m.accel / kGravity_mps2);
    if (m.header.valid & ImuSample::kValidGyro) vec3f(pw.field(sensor::kScaledGyro), m.gyro);
  }
  if (m.saturation != 0) {
    std::uint16_t s = 0;
    if (m.saturation & ImuSample::kSatAccelX) s |= sensor::kOverAccelX;
    if (m.saturation & ImuSample::kSatAccelY) s |= sensor::kOverAccelY;
    if (m.saturation & ImuSample::kSatAccelZ) s |= sensor::kOverAccelZ;
    if (m.saturation & ImuSample::kSatGyroX) s |= sensor::kOverGyroX;
    if (m.saturation & ImuSample::kSatGyroY) s |= sensor::kOverGyroY;
    if (m.saturation & ImuSample::kSatGyroZ) s |= sensor::kOverGyroZ;
    pw.field(sensor::kOverrange).u16(s);
  }
  pw.finish();
  return true;
}

bool encode_gnss_position(const GnssPosition& m, std::vector<std::uint8_t>& out) {
  PacketWriter pw(out, gnss_set(m.receiver_id));
  write_time_fields(m.header, pw);
  const bool has_height = m.header.valid & GnssPosition::kValidHeight;
  const bool has_cov = m.header.valid & GnssPosition::kValidCovariance;
  const auto undulation = geo::egm96_undulation_m(m.lat_rad, m.lon_rad);
  auto& w = pw.field(gnss::kLlh);
  w.f64(m.lat_rad * rot::kRadToDeg);
  w.f64(m.lon_rad * rot::kRadToDeg);
  w.f64(m.height_m);
  w.f64(undulation ? m.height_m - *undulation : 0.0);  // MSL = ellipsoidal - geoid (EGM96)
  // Horizontal accuracy: RMS of the north and east 1-sigma.
  w.f32(static_cast<float>(std::sqrt(0.5 * (m.cov_ned_m2(0, 0) + m.cov_ned_m2(1, 1)))));
  w.f32(static_cast<float>(std::sqrt(m.cov_ned_m2(2, 2))));
  std::uint16_t valid = 0;
  if (m.header.valid & GnssPosition::kValidPosition) valid |= gnss::kLlhValidLatLon;
  if (has_height) valid |= gnss::kLlhValidHeight;
  if (has_height && undulation) valid |= gnss::kLlhValidMsl;
  if (has_cov) valid |= gnss::kLlhValidHAcc | gnss::kLlhValidVAcc;
  w.u16(valid);
  write_fix(pw, m.fix, m.num_sats);
  pw.finish();
  return true;
}

bool encode_gnss_velocity(const GnssVelocity& m, std::vector<std::uint8_t>& out) {
  PacketWriter pw(out, gnss_set(m.receiver_id));
  write_time_fields(m.header, pw);
  const Eigen::Vector3d& v = m.vel_ned_mps;
  const bool has_vel = m.header.valid & GnssVelocity::kValidVelocity;
  const bool has_cov = m.header.valid & GnssVelocity::kValidCovariance;
  auto& w = pw.field(gnss::kVelNed);
  vec3f(w, v);
  w.f32(static_cast<float>(v.norm()));
  w.f32(static_cast<float>(v.head<2>().norm()));
  w.f32(static_cast<float>(rot::wrap_two_pi(std::atan2(v.y(), v.x())) * rot::kRadToDeg));  // course [deg]
  w.f32(static_cast<float>(std::sqrt(m.cov_ned_m2ps2.trace() / 3.0)));  // per-axis RMS 1-sigma
  w.f32(0.0f);
  // bits: 0 velocity, 1 speed_3d, 2 ground_speed, 3 heading, 4 speed_accuracy (L5032)
  std::uint16_t valid = 0;
  if (has_vel) valid |= 0x0F;
  if (has_cov) valid |= gnss::kVelValidSpeedAcc;
  w.u16(valid);
  write_fix(pw, m.fix, 0);
  pw.finish();
  return true;
}

bool encode_gnss_heading(const GnssHeading& m, std::vector<std::uint8_t>& out) {
  PacketWriter pw(out, set::kFilter);
  write_time_fields(m.header, pw);
  auto& w = pw.field(filter::kDualAntennaStatus);
  w.f32(static_cast<float>(time::week_tow_from_gps_ns(m.header.time_ns).tow_s));
  w.f32(static_cast<float>(m.heading_rad));
  w.f32(static_cast<float>(m.heading_std_rad));
  w.u8(m.fix == GnssFixType::kRtkFixed ? filter::kDaFixFixed
       : m.fix == GnssFixType::kRtkFloat ? filter::kDaFixFloat
                                         : filter::kDaFixNone);
  w.u16(kDaStatusBothReceivers);
  w.u16((m.header.valid & GnssHeading::kValidHeading) ? filter::kValid : 0);
  pw.finish();
  return true;
}

bool encode_sensor_scalar(const Measurement& m, std::vector<std::uint8_t>& out) {
  PacketWriter pw(out, set::kSensor);
  write_time_fields(header_of(m), pw);
  if (const auto* mag = std::get_if<Magnetometer>(&m)) {
    vec3f(pw.field(sensor::kScaledMag), mag->field_gauss);
  } else if (const auto* p = std::get_if<Pressure>(&m)) {
    pw.field(sensor::kScaledPressure).f32(static_cast<float>(p->pressure_pa / kMbarToPa));
  } else if (const auto* s = std::get_if<VehicleSpeed>(&m)) {
    const double signed_speed = (!s->is_signed && s->gear == Gear::kReverse) ? -s->speed_mps : s->speed_mps;
    auto& w = pw.field(sensor::kOdometer);
    w.f32(static_cast<float>(signed_speed));
    w.f32(static_cast<float>(s->speed_std_mps));
    w.u16((s->header.valid & VehicleSpeed::kValidSpeed) ? kOdometerConfigured : 0);
  }
  pw.finish();
  return true;
}

// Aiding commands: Time{timebase, reserved, ns}, frame_id, then the measurement (digest §5.3).
void aiding_time(bytes::BeWriter& w, const MeasurementHeader& h, std::uint8_t frame_id) {
  const bool gps = h.time_source == TimeSource::kGps;
  w.u8(static_cast<std::uint8_t>(gps ? AidingTimebase::kExternalTime : AidingTimebase::kInternalReference));
  w.u8(kTimeReserved);
  w.u64(static_cast<std::uint64_t>(h.time_ns < 0 ? 0 : h.time_ns));
  w.u8(frame_id);
}

std::uint8_t lever_arm_frame(PacketWriter& pw, const Eigen::Vector3d& lever_arm_m) {
  if (lever_arm_m.isZero()) return 0;
  auto& w = pw.field(kAidFrameConfig);
  w.u8(static_cast<std::uint8_t>(Function::kWrite));
  w.u8(kLeverArmFrame);
  w.u8(kFormatEuler);
  w.u8(0);  // tracking disabled
  vec3f(w, lever_arm_m);
  vec3f(w, Eigen::Vector3d::Zero());
  return kLeverArmFrame;
}

bool encode_external(const Measurement& m, std::vector<std::uint8_t>& out) {
  PacketWriter pw(out, set::kAiding);
  if (const auto* p = std::get_if<ExternalPosition>(&m)) {
    const std::uint8_t frame = lever_arm_frame(pw, p->lever_arm_m);
    auto& w = pw.field(p->frame == PositionFrame::kEcef ? kAidPosEcef : kAidPosLlh);
    aiding_time(w, p->header, frame);
    const double k = p->frame == PositionFrame::kLlh ? rot::kRadToDeg : 1.0;
    w.f64(p->value.x() * k);
    w.f64(p->value.y() * k);
    w.f64(p->value.z());
    vec3f(w, p->std_m);
    w.u16(static_cast<std::uint16_t>(p->header.valid & 0x7));
  } else if (const auto* v = std::get_if<ExternalVelocity>(&m)) {
    const std::uint8_t frame = lever_arm_frame(pw, v->lever_arm_m);
    const std::uint8_t desc = v->frame == VelocityFrame::kEcef  ? kAidVelEcef
                              : v->frame == VelocityFrame::kNed ? kAidVelNed
                                                                : kAidVelBody;
    auto& w = pw.field(desc);
    aiding_time(w, v->header, frame);
    vec3f(w, v->value_mps);
    vec3f(w, v->std_mps);
    w.u16(static_cast<std::uint16_t>(v->header.valid & 0x7));
  } else if (const auto* h = std::get_if<ExternalHeading>(&m)) {
    auto& w = pw.field(kAidHeading);
    aiding_time(w, h->header, 0);
    w.f32(static_cast<float>(h->heading_rad));
    w.f32(static_cast<float>(h->std_rad));
    w.u16((h->header.valid & ExternalHeading::kValidHeading) ? 1 : 0);
  }
  pw.finish();
  return true;
}

}  // namespace

bool MipEncoder::encode(const Measurement& m, std::vector<std::uint8_t>& out) {
  switch (kind_of(m)) {
    case MeasurementKind::kImu: return encode_imu(std::get<ImuSample>(m), out);
    case MeasurementKind::kGnssPosition: return encode_gnss_position(std::get<GnssPosition>(m), out);
    case MeasurementKind::kGnssVelocity: return encode_gnss_velocity(std::get<GnssVelocity>(m), out);
    case MeasurementKind::kGnssHeading: return encode_gnss_heading(std::get<GnssHeading>(m), out);
    case MeasurementKind::kDeviceSolution: encode_solution(std::get<NavSolution>(m), out); return true;
    case MeasurementKind::kMagnetometer:
    case MeasurementKind::kPressure:
    case MeasurementKind::kVehicleSpeed: return encode_sensor_scalar(m, out);
    case MeasurementKind::kExternalPosition:
    case MeasurementKind::kExternalVelocity:
    case MeasurementKind::kExternalHeading: return encode_external(m, out);
    case MeasurementKind::kWheelSpeed:
    case MeasurementKind::kWheelTicks:
    case MeasurementKind::kCount: return false;
  }
  return false;
}

}  // namespace navfuse::frontends::mip

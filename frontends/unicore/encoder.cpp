#include "frontends/unicore/encoder.hpp"

#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/nmea/sentences.hpp"
#include "frontends/unicore/messages.hpp"
#include "frontends/unicore/to_core.hpp"

namespace navfuse::frontends::unicore {
namespace {

using time::kNsPerSecond;

constexpr std::int64_t kNsPerMs = 1'000'000;
constexpr double kSToMs = 1e3;
// Printed decimals, from the spec's examples and tables.
constexpr int kGyoaccTimeDecimals = 3;   // hhmmss.sss (L745)
constexpr int kNavaccTimeDecimals = 2;   // "085206.00" (L1353)
constexpr int kNavattTimeDecimals = 2;   // hhmmss.ss (L1378)
constexpr int kEcefDecimals = 3;         // "-2160481.168" (L1282)
constexpr int kLatLonDegDecimals = 6;    // "40.078998" (L1282)
constexpr int kNavposHeightDecimals = 6; // "52.843847" (L1282)
constexpr int kVelocityDecimals = 3;     // "0.000" (L1305)
constexpr int kNavtimeTowDecimals = 9;   // "99974.000222664" (L1325)
constexpr int kGstStdDecimals = 2;       // "0.07" (L1064)
// h51 / h30 GGA formats (L875-L884 / L1096-L1105).
constexpr int kH51TimeDecimals = 2, kH30TimeDecimals = 3;
constexpr int kH51LatMinuteDecimals = 6, kH30LatMinuteDecimals = 7;
constexpr int kLonMinuteDecimals = 6;
constexpr int kH51HeightDecimals = 1, kH30HeightDecimals = 3;
constexpr std::uint32_t kQualityPrecise = 3;
// GNSS week offsets and the GLONASS day (digest §4.7, checked on the NAVTIME example):
// BDT week = GPS week - 1356, BDT = GPST - 14 s; GST week = GPS week - 1024, GST = GPST.
constexpr std::int32_t kBdsWeekOffset = 1356;
constexpr std::int64_t kGpsMinusBdsNs = 14 * kNsPerSecond;
constexpr std::int32_t kGalWeekOffset = 1024;
constexpr std::int64_t kMoscowMinusUtcNs = 3 * 3600 * kNsPerSecond;
constexpr int kGlonassFirstIntervalYear = 1996;  // N4 = 1 for 1996-1999 (GLONASS ICD 5.1)
constexpr int kYearsPerInterval = 4;

std::int64_t round_to(std::int64_t ns, std::int64_t unit) {
  const std::int64_t r = ((ns % unit) + unit) % unit;
  return r * 2 >= unit ? ns - r + unit : ns - r;
}

std::int64_t pow10_ns(int decimals) {
  std::int64_t unit = kNsPerSecond;
  for (int i = 0; i < decimals; ++i) unit /= 10;
  return unit;
}

// UTC date and time of day of a GPS time rounded to the printed resolution (so that the date
// and the time agree at midnight).
void utc_fields(std::int64_t gps_ns, int decimals, nmea::Date& date, nmea::TimeOfDay& tod) {
  const std::int64_t unix_ns = round_to(time::unix_ns_from_gps_ns(gps_ns), pow10_ns(decimals));
  const std::int64_t day_ns = ((unix_ns % nmea::kNsPerDay) + nmea::kNsPerDay) % nmea::kNsPerDay;
  const time::UtcDateTime utc = time::utc_from_unix_ns(unix_ns - day_ns);
  date = {utc.year, utc.month, utc.day};
  tod = {day_ns, decimals};
}

nmea::TimeOfDay utc_time_of_day(std::int64_t gps_ns, int decimals) {
  nmea::Date d;
  nmea::TimeOfDay t;
  utc_fields(gps_ns, decimals, d, t);
  return t;
}

Real real(double v, int decimals) { return Real{v, decimals}; }

std::int32_t e5deg(double rad) {
  return static_cast<std::int32_t>(std::llround(rad * rot::kRadToDeg / kNavattDegPerUnit));
}
std::uint32_t e5deg_u(double rad) {
  return static_cast<std::uint32_t>(std::llround(std::fabs(rad) * rot::kRadToDeg / kNavattDegPerUnit));
}

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

}  // namespace

bool UnicoreEncoder::encode(const Measurement& m, std::vector<std::uint8_t>& out) {
  const std::size_t before = out.size();
  bool ok = false;
  switch (kind_of(m)) {
    case MeasurementKind::kImu: ok = encode_imu(std::get<ImuSample>(m), out); break;
    case MeasurementKind::kGnssPosition: ok = encode_position(std::get<GnssPosition>(m), out); break;
    case MeasurementKind::kGnssVelocity: ok = encode_velocity(std::get<GnssVelocity>(m), out); break;
    case MeasurementKind::kDeviceSolution: ok = encode_solution(std::get<NavSolution>(m), out); break;
    case MeasurementKind::kWheelTicks: note_ticks(std::get<WheelTicks>(m)); return true;
    case MeasurementKind::kVehicleSpeed: return note_speed(std::get<VehicleSpeed>(m));
    default: return false;
  }
  if (!ok) out.resize(before);  // all or nothing
  return ok;
}

void UnicoreEncoder::ensure_navtime(std::int64_t gps_ns, std::vector<std::uint8_t>& out) {
  const std::int64_t second = gps_ns / kNsPerSecond;
  if (!options_.write_navtime || navtime_second_ == second) return;
  navtime_second_ = second;
  const time::WeekTow gps = time::week_tow_from_gps_ns(gps_ns);
  const time::WeekTow bds = time::week_tow_from_gps_ns(gps_ns - kGpsMinusBdsNs);
  Navtime m;
  m.gps_week = static_cast<std::uint32_t>(gps.week);
  m.gps_tow_s = real(gps.tow_s, kNavtimeTowDecimals);
  m.gps_quality = kQualityPrecise;
  m.bds_week = static_cast<std::uint32_t>(bds.week - kBdsWeekOffset);
  m.bds_tow_s = real(bds.tow_s, kNavtimeTowDecimals);
  m.bds_quality = kQualityPrecise;
  m.gal_week = static_cast<std::uint32_t>(gps.week - kGalWeekOffset);
  m.gal_tow_s = m.gps_tow_s;
  m.gal_quality = kQualityPrecise;
  // GLONASS: Moscow date as 4-year interval + day in it, and Moscow time of day.
  const std::int64_t msk_ns = time::unix_ns_from_gps_ns(gps_ns) + kMoscowMinusUtcNs;
  const std::int64_t msk_day_ns = ((msk_ns % nmea::kNsPerDay) + nmea::kNsPerDay) % nmea::kNsPerDay;
  const time::UtcDateTime msk = time::utc_from_unix_ns(msk_ns - msk_day_ns);
  const int interval_start = msk.year - (msk.year - kGlonassFirstIntervalYear) % kYearsPerInterval;
  const auto start_ns = time::unix_ns_from_utc(time::UtcDateTime{interval_start, 1, 1, 0, 0, 0.0});
  m.glo_four_year = static_cast<std::uint32_t>((msk.year - kGlonassFirstIntervalYear) / kYearsPerInterval + 1);
  m.glo_day = static_cast<std::uint32_t>((msk_ns - msk_day_ns - start_ns.value_or(0)) / nmea::kNsPerDay + 1);
  m.glo_time_of_day_s = real(time::seconds(msk_day_ns), kNavtimeTowDecimals);
  m.glo_quality = kQualityPrecise;
  unicore::encode(m, out);
}

bool UnicoreEncoder::encode_imu(const ImuSample& s, std::vector<std::uint8_t>& out) {
  Eigen::Vector3d gyro = s.gyro, accel = s.accel;
  if (s.quantity == ImuQuantity::kIncrements) {
    if (!(s.dt_s > 0.0)) return false;
    gyro /= s.dt_s;
    accel /= s.dt_s;
  }
  if (!finite(gyro) || !finite(accel)) return false;
  const bool vehicle = s.frame == SensorFrame::kVehicle;
  if (vehicle) {
    gyro = rfu_from_frd(gyro);
    accel = rfu_from_frd(accel);
  }
  const std::int64_t t = s.header.time_ns;
  ensure_navtime(t, out);
  Gyoacc m;
  m.vehicle_frame = vehicle;
  nmea::Date date;
  nmea::TimeOfDay tod;
  utc_fields(t, kGyoaccTimeDecimals, date, tod);
  m.date = date;
  m.time = tod;
  const auto period_ms = s.dt_s > 0.0 ? static_cast<std::uint32_t>(std::llround(s.dt_s * kSToMs))
                                      : options_.default_imu_period_ms;
  for (int i = 0; i < 3; ++i) {
    m.gyro_rps[static_cast<std::size_t>(i)] = real(gyro[i], kImuDecimals);
    m.accel_mps2[static_cast<std::size_t>(i)] = real(accel[i], kImuDecimals);
  }
  m.gyro_period_ms = period_ms;
  m.accel_period_ms = period_ms;
  if (have_odometer_) {
    const auto whole = static_cast<std::uint32_t>(std::floor(pending_pulses_));
    pending_pulses_ -= whole;
    m.pulses = latest_ticks_ - ticks_at_last_gyoacc_ + whole;
    m.pulse_period_ms = last_gyoacc_ns_ ? static_cast<std::uint32_t>(std::llround(
                                              static_cast<double>(t - *last_gyoacc_ns_) / kNsPerMs))
                                        : period_ms;
    if (m.pulse_period_ms == 0) m.pulse_period_ms = period_ms;
    m.reverse = reverse_ ? 1 : 0;
    if (!vehicle) ticks_at_last_gyoacc_ = latest_ticks_;
  }
  if (!vehicle) last_gyoacc_ns_ = t;
  return unicore::encode(m, out);
}

void UnicoreEncoder::note_ticks(const WheelTicks& t) {
  have_odometer_ = true;
  latest_ticks_ = t.ticks[0];
  reverse_ = t.gear == Gear::kReverse;
}

bool UnicoreEncoder::note_speed(const VehicleSpeed& v) {
  if (!(options_.odometer_m_per_pulse > 0.0) || !std::isfinite(v.speed_mps)) return false;
  have_odometer_ = true;
  reverse_ = v.gear == Gear::kReverse || (v.is_signed && v.speed_mps < 0.0);
  if (last_speed_ns_) {
    const double dt = time::seconds(v.header.time_ns - *last_speed_ns_);
    if (dt > 0.0) pending_pulses_ += std::fabs(v.speed_mps) * dt / options_.odometer_m_per_pulse;
  }
  last_speed_ns_ = v.header.time_ns;
  return true;
}

bool UnicoreEncoder::encode_position(const GnssPosition& p, std::vector<std::uint8_t>& out) {
  if (!std::isfinite(p.lat_rad) || !std::isfinite(p.lon_rad) || !std::isfinite(p.height_m)) return false;
  const std::int64_t t = p.header.time_ns;
  ensure_navtime(t, out);
  if (p.header.valid & GnssPosition::kValidCovariance) {
    Navacc acc;
    acc.time = utc_time_of_day(t, kNavaccTimeDecimals);
    acc.status = 'A';
    const double h_rms = std::sqrt(p.cov_ned_m2(0, 0) + p.cov_ned_m2(1, 1));
    if (!std::isfinite(h_rms)) return false;
    acc.pos_acc_mm = static_cast<std::uint32_t>(std::llround(h_rms / kMillimetre));
    acc.vel_acc_mmps = vel_acc_mmps_;
    if (!unicore::encode(acc, out)) return false;
  }
  Navpos m;
  m.time_ms = static_cast<std::uint32_t>(std::llround(time::week_tow_from_gps_ns(t).tow_s * kSToMs));
  m.system = options_.navpos_system_mask;
  m.quality = quality_from_fix(p.fix);
  const Eigen::Vector3d ecef = geo::ecef_from_llh({p.lat_rad, p.lon_rad, p.height_m});
  for (int i = 0; i < 3; ++i) m.ecef_m[static_cast<std::size_t>(i)] = real(ecef[i], kEcefDecimals);
  m.lat_deg = real(p.lat_rad * rot::kRadToDeg, kLatLonDegDecimals);
  m.lon_deg = real(p.lon_rad * rot::kRadToDeg, kLatLonDegDecimals);
  m.height_m = real(p.height_m, kNavposHeightDecimals);
  lat_lon_rad_ = {p.lat_rad, p.lon_rad};
  return unicore::encode(m, out);
}

bool UnicoreEncoder::encode_velocity(const GnssVelocity& v, std::vector<std::uint8_t>& out) {
  if (!lat_lon_rad_ || !finite(v.vel_ned_mps)) return false;
  const std::int64_t t = v.header.time_ns;
  ensure_navtime(t, out);
  if (v.header.valid & GnssVelocity::kValidCovariance) {
    const double rms = std::sqrt(v.cov_ned_m2ps2(0, 0) + v.cov_ned_m2ps2(1, 1));
    if (std::isfinite(rms)) vel_acc_mmps_ = static_cast<std::uint32_t>(std::llround(rms / kMillimetre));
  }
  Navvel m;
  m.time_ms = static_cast<std::uint32_t>(std::llround(time::week_tow_from_gps_ns(t).tow_s * kSToMs));
  m.system = options_.navpos_system_mask;
  m.quality = quality_from_fix(v.fix);
  const Eigen::Vector3d ecef =
      geo::rot_ecef_from_ned(lat_lon_rad_->first, lat_lon_rad_->second) * v.vel_ned_mps;
  for (int i = 0; i < 3; ++i) m.vel_ecef_mps[static_cast<std::size_t>(i)] = real(ecef[i], kVelocityDecimals);
  m.clock_drift_mps = real(0.0, kVelocityDecimals);
  return unicore::encode(m, out);
}

bool UnicoreEncoder::encode_solution(const NavSolution& s, std::vector<std::uint8_t>& out) {
  const std::int64_t t = s.header.time_ns;
  const bool h30 = options_.dialect == nmea::Dialect::kH30;
  const bool has_pos = (s.header.valid & NavSolution::kValidPosition) != 0;
  if (has_pos && (!std::isfinite(s.lat_rad) || !std::isfinite(s.lon_rad) || !std::isfinite(s.height_m))) {
    return false;
  }
  ensure_navtime(t, out);
  if (s.device_status != 0 && last_status_ != s.device_status) {
    last_status_ = s.device_status;
    if (!unicore::encode(unpack_snrstat(s.device_status), out)) return false;
  }
  const int time_decimals = h30 ? kH30TimeDecimals : kH51TimeDecimals;
  if (has_pos && (s.header.valid & NavSolution::kValidPositionStd)) {
    nmea::Gst gst;
    gst.talker = options_.talker;
    gst.time = utc_time_of_day(t, time_decimals);
    gst.std_lat_m = real(s.pos_std_ned_m.x(), kGstStdDecimals);
    gst.std_lon_m = real(s.pos_std_ned_m.y(), kGstStdDecimals);
    gst.std_alt_m = real(s.pos_std_ned_m.z(), kGstStdDecimals);
    if (!finite(s.pos_std_ned_m) || !nmea::encode(gst, out)) return false;
  }
  nmea::Gga gga;
  gga.talker = options_.talker;
  gga.time = utc_time_of_day(t, time_decimals);
  gga.quality = gga_quality_from_solution(s);
  gga.height_unit = has_pos;
  if (has_pos) {
    gga.lat = nmea::LatLonField{s.lat_rad * rot::kRadToDeg, h30 ? kH30LatMinuteDecimals : kH51LatMinuteDecimals};
    gga.lon = nmea::LatLonField{s.lon_rad * rot::kRadToDeg, kLonMinuteDecimals};
    // CFGGEOID 0 (default, L1557): the "msl" field carries the ellipsoidal height, Altref empty.
    gga.height_m = real(s.height_m, h30 ? kH30HeightDecimals : kH51HeightDecimals);
  }
  if (!nmea::encode(gga, out)) return false;
  if (s.header.valid & NavSolution::kValidAttitude) {
    if (!finite(s.rpy_rad) || !finite(s.att_std_rpy_rad)) return false;
    Navatt att;
    att.time = utc_time_of_day(t, kNavattTimeDecimals);
    att.quality = kNavattRollValid | kNavattPitchValid |
                  ((s.header.valid & NavSolution::kValidHeading) ? kNavattYawValid : 0u);
    att.roll_e5deg = e5deg(s.rpy_rad.x());
    att.pitch_e5deg = e5deg(s.rpy_rad.y());
    att.yaw_e5deg = e5deg(rot::wrap_two_pi(s.rpy_rad.z()));  // 0 ~ 360E+5 (L1383)
    att.roll_std_e5deg = e5deg_u(s.att_std_rpy_rad.x());
    att.pitch_std_e5deg = e5deg_u(s.att_std_rpy_rad.y());
    att.yaw_std_e5deg = e5deg_u(s.att_std_rpy_rad.z());
    if (!unicore::encode(att, out)) return false;
  }
  return true;
}

}  // namespace navfuse::frontends::unicore

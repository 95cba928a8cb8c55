#include "frontends/vectornav/decoder_ascii.hpp"

#include <array>
#include <charconv>
#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/vectornav/ascii_registers.hpp"
#include "frontends/vectornav/ins_status.hpp"
#include "frontends/vectornav/to_core.hpp"

namespace navfuse::frontends::vectornav {
namespace {

using rot::kDegToRad;

constexpr std::string_view kHeaderRead = "VNRRG";
constexpr std::string_view kHeaderWrite = "VNWRG";
constexpr std::string_view kHeaderError = "VNERR";
// Command echoes (§1.3, L178-581): valid frames without measurement content. VNTAR is the
// legacy tare command, absent from this ICD (digest §6.9) but still echoed by older firmware.
constexpr std::array<std::string_view, 12> kCommandEchoes = {"VNWNV", "VNRFS", "VNRST", "VNFWU", "VNKMD", "VNKAD",
                                                             "VNSIH", "VNASY", "VNSFB", "VNSBL", "VNBOM", "VNTAR"};
constexpr double kPercentConverged = 100.0;  // Reg 98 PercentComplete when the compass is ready

// Errata A32 (digest §10; L89, L3254-3258): field widths differ between firmware and legacy
// modes (Reg 206), so fields are parsed as numbers between commas, never by column.
bool parse_number(std::string_view s, bool hex, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  if (hex) {
    std::uint32_t v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v, 16);
    if (ec != std::errc{} || p != s.data() + s.size()) return false;
    out = v;
    return true;
  }
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc{} && p == s.data() + s.size();
}

// A parsed field as an integer in [0, max], or nullopt (not integral, out of range, NaN: from_chars
// accepts "nan" and "inf", and casting those to an integer would be undefined).
std::optional<unsigned> integral(double x, double max) {
  if (!(x >= 0.0 && x <= max) || x != std::floor(x)) return std::nullopt;
  return static_cast<unsigned>(x);
}

Eigen::Vector3d v3(std::span<const double> v, std::size_t at) { return {v[at], v[at + 1], v[at + 2]}; }

// Field offsets shared by the GNSS (58/59/103/104) and INS (63/64) solution registers.
namespace gnss_at {
constexpr std::size_t kTow = 0, kWeek = 1, kFix = 2, kNumSats = 3, kPos = 4, kVel = 7, kPosStd = 10, kVelStd = 13;
}
namespace ins_at {
constexpr std::size_t kTow = 0, kWeek = 1, kStatus = 2, kYpr = 3, kPos = 6, kVel = 9, kAttStd = 12, kPosStd = 13,
                      kVelStd = 14;
}

Eigen::Vector3d rpy_from_ypr_deg(const Eigen::Vector3d& ypr_deg) {
  return Eigen::Vector3d(ypr_deg.z(), ypr_deg.y(), ypr_deg.x()) * kDegToRad;
}

std::optional<Stamp> gps_stamp(double week, double tow_s) {
  if (!(week > 0 && week <= kMaxPlausibleGpsWeek && tow_s >= 0 && tow_s < static_cast<double>(time::kSecondsPerWeek)))
    return std::nullopt;
  return Stamp{time::gps_ns_from_week_tow(static_cast<std::int32_t>(week), tow_s), TimeSource::kGps};
}

template <class M>
void stamp_header(M& m, const Stamp& s) {
  m.header.time_ns = s.time_ns;
  m.header.time_source = s.source;
}

}  // namespace

std::string_view vn_error_name(unsigned code) {
  switch (code) {
    case 0x01: return "hard_fault";
    case 0x02: return "serial_buffer_overflow";
    case 0x03: return "invalid_checksum";
    case 0x04: return "invalid_command";
    case 0x05: return "not_enough_parameters";
    case 0x06: return "too_many_parameters";
    case 0x07: return "invalid_parameter";
    case 0x08: return "invalid_register";
    case 0x09: return "unauthorized_access";
    case 0x0A: return "watchdog_reset";
    case 0x0B: return "output_buffer_overflow";
    case 0x0C: return "insufficient_baud_rate";
    case 0xFF: return "error_buffer_overflow";
    default: return "unknown";
  }
}

AsciiOutcome AsciiMapper::handle(const AsciiSentence& s, DecodeSink& sink, FrameRecord* record) {
  if (record) record->name = std::string(s.header);
  const auto values = s.values();
  if (s.header == kHeaderError) {
    double code = 0;
    if (values.size() != 1 || !parse_number(values[0], true, code)) return AsciiOutcome::kError;
    if (record) {
      record->fields.emplace_back("error_code", static_cast<std::uint64_t>(code));
      record->fields.emplace_back("error_name", std::string(vn_error_name(static_cast<unsigned>(code))));
    }
    return AsciiOutcome::kDecoded;
  }
  if (s.header == kHeaderRead || s.header == kHeaderWrite) {
    double id = 0;
    // Errata A24: the id may be zero-padded ("05") or not ("5"); it is decimal either way.
    if (values.empty() || !parse_number(values[0], false, id) || id < 0 || id > 255 || id != std::floor(id))
      return AsciiOutcome::kError;
    if (record) record->fields.emplace_back("register", static_cast<std::uint64_t>(id));
    // A read request as the host sends it (a port logged in both directions) has only the id.
    if (s.header == kHeaderRead && values.size() == 1) return AsciiOutcome::kDecoded;
    return handle_register(static_cast<int>(id), values.subspan(1), sink, record);
  }
  if (const RegisterLayout* layout = find_async_output(s.header)) {
    if (record) {
      if (s.has_append_count) record->fields.emplace_back("append_count", std::uint64_t{s.append_count});
      if (s.has_append_status) record->fields.emplace_back("append_status", std::uint64_t{s.append_status});
    }
    return handle_register(layout->id, values, sink, record);
  }
  for (std::string_view echo : kCommandEchoes) {
    if (s.header == echo) {
      if (record)
        for (std::size_t i = 0; i < values.size(); ++i)
          record->fields.emplace_back("param" + std::to_string(i), std::string(values[i]));
      return AsciiOutcome::kDecoded;
    }
  }
  return AsciiOutcome::kUnknown;
}

AsciiOutcome AsciiMapper::handle_register(int id, std::span<const std::string_view> values, DecodeSink& sink,
                                          FrameRecord* record) {
  const RegisterLayout* layout = find_register(id);
  // Binary output configuration (Reg 75-77) has a variable number of hex group bytes and type
  // words (errata A16), and unknown registers are listed verbatim.
  if (layout == nullptr) {
    if (record)
      for (std::size_t i = 0; i < values.size(); ++i)
        record->fields.emplace_back("param" + std::to_string(i), std::string(values[i]));
    return AsciiOutcome::kDecoded;
  }
  // Trailing optional fields (SerialPort of Reg 5-7, L2617-2717) may be absent.
  if (values.size() > layout->fields.size() || values.size() + 1 < layout->fields.size() ||
      (values.size() < layout->fields.size() && !layout->async_header.empty()))
    return AsciiOutcome::kError;
  std::array<double, kMaxAsciiFields> v{};
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!parse_number(values[i], (layout->hex_fields >> i) & 1u, v[i])) return AsciiOutcome::kError;
  if (record)
    for (std::size_t i = 0; i < values.size(); ++i)
      record->fields.emplace_back(std::string(layout->fields[i]), v[i]);
  return map_register(id, std::span<const double>(v.data(), values.size()), sink) ? AsciiOutcome::kDecoded
                                                                                 : AsciiOutcome::kError;
}

bool AsciiMapper::map_register(int id, std::span<const double> v, DecodeSink& sink) {
  Stamp stamp = clock_.latest();
  auto imu = [&](const Eigen::Vector3d* gyro, const Eigen::Vector3d* accel) {
    ImuSample s;
    stamp_header(s, stamp);
    s.frame = options_.imu_frame;
    if (gyro) {
      s.gyro = *gyro;
      s.header.valid |= ImuSample::kValidGyro;
    }
    if (accel) {
      s.accel = *accel;
      s.header.valid |= ImuSample::kValidAccel;
    }
    sink.on_measurement(s);
  };
  auto mag = [&](const Eigen::Vector3d& field) {
    Magnetometer m;
    stamp_header(m, stamp);
    m.frame = options_.imu_frame;
    m.field_gauss = field;
    m.header.valid = Magnetometer::kValidField;
    sink.on_measurement(m);
  };
  auto attitude = [&](const Eigen::Quaterniond& q, const Eigen::Vector3d& rpy) {
    NavSolution s;
    stamp_header(s, stamp);
    s.mode = NavMode::kAhrs;
    s.q_nb = q;
    s.rpy_rad = rpy;
    s.header.valid = NavSolution::kValidAttitude | NavSolution::kValidHeading;
    return s;
  };
  auto from_ypr = [&](std::size_t at) {
    const Eigen::Vector3d rpy = rpy_from_ypr_deg(v3(v, at));
    return attitude(rot::quat_from_rpy(rpy), rpy);
  };
  auto gnss = [&](std::uint8_t receiver, bool ecef) {
    const auto fix_field = integral(v[gnss_at::kFix], 255);
    const auto num_sats = integral(v[gnss_at::kNumSats], 255);
    if (!fix_field || !num_sats) return false;
    const auto fix = fix_from_vn(static_cast<std::uint8_t>(*fix_field));
    if (!fix) return false;
    if (const auto s = gps_stamp(v[gnss_at::kWeek], v[gnss_at::kTow])) {
      stamp = *s;
      clock_.note_gps(s->time_ns);
    }
    GnssPosition p;
    stamp_header(p, stamp);
    geo::Llh llh{v[gnss_at::kPos] * kDegToRad, v[gnss_at::kPos + 1] * kDegToRad, v[gnss_at::kPos + 2]};
    if (ecef) llh = geo::llh_from_ecef(v3(v, gnss_at::kPos));
    p.lat_rad = llh.lat_rad;
    p.lon_rad = llh.lon_rad;
    p.height_m = llh.height_m;
    p.fix = *fix;
    p.num_sats = static_cast<std::uint8_t>(*num_sats);
    p.receiver_id = receiver;
    const Eigen::Vector3d sd = v3(v, gnss_at::kPosStd);
    const Eigen::Matrix3d c_en = geo::rot_ecef_from_ned(llh.lat_rad, llh.lon_rad);
    const Eigen::Matrix3d d = sd.cwiseProduct(sd).asDiagonal();
    // Reg 59/104 give ECEF X/Y/Z sigmas: rotate that covariance into NED.
    p.cov_ned_m2 = ecef ? Eigen::Matrix3d(c_en.transpose() * d * c_en) : d;
    const bool usable = *fix >= GnssFixType::kFix2D;
    p.header.valid = GnssPosition::kValidCovariance;
    if (usable) p.header.valid |= GnssPosition::kValidPosition;
    if (usable && *fix != GnssFixType::kFix2D) p.header.valid |= GnssPosition::kValidHeight;
    sink.on_measurement(p);
    GnssVelocity vel;
    stamp_header(vel, stamp);
    vel.vel_ned_mps = ecef ? Eigen::Vector3d(c_en.transpose() * v3(v, gnss_at::kVel)) : v3(v, gnss_at::kVel);
    vel.cov_ned_m2ps2 = Eigen::Matrix3d::Identity() * (v[gnss_at::kVelStd] * v[gnss_at::kVelStd]);
    vel.fix = *fix;
    vel.receiver_id = receiver;
    vel.header.valid = GnssVelocity::kValidCovariance | (usable ? GnssVelocity::kValidVelocity : 0u);
    sink.on_measurement(vel);
    return true;
  };
  auto ins = [&](bool ecef) -> bool {
    if (const auto s = gps_stamp(v[ins_at::kWeek], v[ins_at::kTow])) {
      stamp = *s;
      clock_.note_gps(s->time_ns);
    }
    NavSolution s = from_ypr(ins_at::kYpr);
    const auto status = integral(v[ins_at::kStatus], 65535);
    if (!status) return false;
    const auto raw = static_cast<std::uint16_t>(*status);
    const InsStatus st = decode_ins_status(raw);
    s.device_status = raw;
    s.mode = nav_mode_of(st, s.rpy_rad.cwiseAbs().maxCoeff() > 0.0);
    s.status_flags = status_flags_of(st);
    s.gnss_fix = st.gnss_fix ? GnssFixType::kFix3D : GnssFixType::kNone;
    InsValidity ok = validity_of(st.mode);
    if (st.mode == InsMode::kNotTracking && s.mode == NavMode::kAhrs) ok.attitude = true;
    geo::Llh llh{v[ins_at::kPos] * kDegToRad, v[ins_at::kPos + 1] * kDegToRad, v[ins_at::kPos + 2]};
    if (ecef) llh = geo::llh_from_ecef(v3(v, ins_at::kPos));
    s.lat_rad = llh.lat_rad;
    s.lon_rad = llh.lon_rad;
    s.height_m = llh.height_m;
    s.vel_ned_mps = ecef ? Eigen::Vector3d(geo::rot_ecef_from_ned(llh.lat_rad, llh.lon_rad).transpose() *
                                           v3(v, ins_at::kVel))
                         : v3(v, ins_at::kVel);
    s.att_std_rpy_rad.setConstant(v[ins_at::kAttStd] * kDegToRad);
    s.pos_std_ned_m.setConstant(v[ins_at::kPosStd]);
    s.vel_std_ned_mps.setConstant(v[ins_at::kVelStd]);
    s.header.valid = 0;
    if (ok.attitude)
      s.header.valid |= NavSolution::kValidAttitude | NavSolution::kValidHeading | NavSolution::kValidAttitudeStd;
    if (ok.position_velocity)
      s.header.valid |= NavSolution::kValidPosition | NavSolution::kValidVelocity | NavSolution::kValidPositionStd |
                        NavSolution::kValidVelocityStd;
    sink.on_measurement(s);
    return true;
  };
  auto ins_state = [&](bool ecef) {
    NavSolution s = from_ypr(0);
    geo::Llh llh{v[3] * kDegToRad, v[4] * kDegToRad, v[5]};
    if (ecef) llh = geo::llh_from_ecef(v3(v, 3));
    s.mode = NavMode::kNavigation;
    s.lat_rad = llh.lat_rad;
    s.lon_rad = llh.lon_rad;
    s.height_m = llh.height_m;
    s.vel_ned_mps = ecef ? Eigen::Vector3d(geo::rot_ecef_from_ned(llh.lat_rad, llh.lon_rad).transpose() * v3(v, 6))
                         : v3(v, 6);
    s.angular_rate_rps = v3(v, 12);
    s.header.valid |= NavSolution::kValidPosition | NavSolution::kValidVelocity;
    sink.on_measurement(s);
  };

  switch (id) {
    case reg::kYpr: sink.on_measurement(from_ypr(0)); return true;
    case reg::kQuaternion:
    case reg::kQuatMagAccelGyro: {
      Eigen::Quaterniond q(v[3], v[0], v[1], v[2]);  // scalar last (Reg 9, L4411-4426)
      if (!(q.norm() > 0)) return false;
      q.normalize();
      sink.on_measurement(attitude(q, rot::rpy_from_quat(q)));
      if (id == reg::kQuatMagAccelGyro) {
        const Eigen::Vector3d g = v3(v, 10), a = v3(v, 7);
        mag(v3(v, 4));
        imu(&g, &a);
      }
      return true;
    }
    case reg::kMag: mag(v3(v, 0)); return true;
    case reg::kAccel: {
      const Eigen::Vector3d a = v3(v, 0);
      imu(nullptr, &a);
      return true;
    }
    case reg::kGyro: {
      const Eigen::Vector3d g = v3(v, 0);
      imu(&g, nullptr);
      return true;
    }
    case reg::kMagAccelGyro: {
      const Eigen::Vector3d a = v3(v, 3), g = v3(v, 6);
      mag(v3(v, 0));
      imu(&g, &a);
      return true;
    }
    case reg::kYprMagAccelGyro: {
      const Eigen::Vector3d a = v3(v, 6), g = v3(v, 9);
      sink.on_measurement(from_ypr(0));
      mag(v3(v, 3));
      imu(&g, &a);
      return true;
    }
    case reg::kYprLinBodyGyro:
    case reg::kYprLinNedGyro: {
      NavSolution s = from_ypr(0);
      s.angular_rate_rps = v3(v, 6);
      if (id == reg::kYprLinBodyGyro) s.linear_accel_mps2 = v3(v, 3);
      sink.on_measurement(s);
      return true;
    }
    case reg::kImuMeasurements: {
      const Eigen::Vector3d a = v3(v, 3), g = v3(v, 6);
      mag(v3(v, 0));
      imu(&g, &a);
      Pressure p;
      stamp_header(p, stamp);
      p.pressure_pa = v[10] * 1e3;  // kPa
      p.header.valid = Pressure::kValidPressure;
      sink.on_measurement(p);
      return true;
    }
    case reg::kGnssLla: return gnss(0, false);
    case reg::kGnssEcef: return gnss(0, true);
    case reg::kGnss2Lla: return gnss(1, false);
    case reg::kGnss2Ecef: return gnss(1, true);
    case reg::kInsLla: return ins(false);
    case reg::kInsEcef: return ins(true);
    case reg::kInsStateLla: ins_state(false); return true;
    case reg::kInsStateEcef: ins_state(true); return true;
    case reg::kDeltaThetaVel: {
      if (!(v[0] > 0.0 && std::isfinite(v[0]))) return false;
      ImuSample s;
      stamp_header(s, stamp);
      s.frame = options_.imu_frame;
      s.quantity = ImuQuantity::kIncrements;
      s.increments = ImuIncrements::kCompensated;  // as the binary DeltaTheta/DeltaVel (ICD 2.4.7-2.4.8)
      s.dt_s = v[0];
      s.gyro = v3(v, 1) * kDegToRad;  // DeltaTheta in degrees (Reg 80, L4640-4674)
      s.accel = v3(v, 4);
      s.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
      sink.on_measurement(s);
      return true;
    }
    case reg::kCompassStartup: {
      // Reg 98 (L5177-5191): the GNSS compass' start-up progress and current heading. The
      // only GNSS-compass heading this ICD outputs (digest §5.9).
      GnssHeading h;
      stamp_header(h, stamp);
      h.heading_rad = rot::wrap_pi(v[1] * kDegToRad);
      h.heading_std_rad = options_.compass_heading_std_deg * kDegToRad;
      const bool ready = v[0] >= kPercentConverged;
      h.fix = ready ? GnssFixType::kRtkFixed : GnssFixType::kNone;
      h.header.valid = ready ? GnssHeading::kValidHeading : 0u;
      sink.on_measurement(h);
      return true;
    }
    case reg::kVelAidMeasurement: {
      // Reg 50 (L3711-3734): the speed the host fed the device; the device uses only the
      // vector's length, as body-x speed, so it is a magnitude.
      VehicleSpeed s;
      stamp_header(s, stamp);
      s.speed_mps = v3(v, 0).norm();
      s.is_signed = false;
      s.header.valid = VehicleSpeed::kValidSpeed;
      sink.on_measurement(s);
      return true;
    }
    default: return true;  // configuration registers: FrameRecord only
  }
}

}  // namespace navfuse::frontends::vectornav

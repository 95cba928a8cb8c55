#include "frontends/mip/decoder.hpp"

#include <bit>
#include <cmath>
#include <cstring>

#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/mip/filter_status.hpp"
#include "frontends/mip/frame_record.hpp"
#include "frontends/mip/gnss_fix.hpp"
#include "frontends/mip/units.hpp"

namespace navfuse::frontends::mip {
namespace {

// Big-endian loads from a field whose length has been checked (digest §2.4: all big-endian).
inline std::uint16_t be16(const std::uint8_t* p) { return static_cast<std::uint16_t>((p[0] << 8) | p[1]); }
inline std::uint32_t be32(const std::uint8_t* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  return std::endian::native == std::endian::little ? __builtin_bswap32(v) : v;
}
inline std::uint64_t be64(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return std::endian::native == std::endian::little ? __builtin_bswap64(v) : v;
}
inline double f32(const std::uint8_t* p) { return static_cast<double>(std::bit_cast<float>(be32(p))); }
inline double f64(const std::uint8_t* p) { return std::bit_cast<double>(be64(p)); }
inline Eigen::Vector3d v3f(const std::uint8_t* p) { return {f32(p), f32(p + 4), f32(p + 8)}; }

// Field data sizes (digest §4.7 computed lengths minus the 2-byte field header).
constexpr std::size_t kVec3fSize = 12;
constexpr std::size_t kVec3fValidSize = 14;        // vector3f + u16 valid (0x82 vectors)
constexpr std::size_t kGpsTimeSize = 12;           // f64 tow, u16 week, u16 valid
constexpr std::size_t kRefTimeSize = 8;            // u64 ns
constexpr std::size_t kDeltaSize = 8;              // u64 ns or f64 s
constexpr std::size_t kPressureSize = 4;
constexpr std::size_t kOverrangeSize = 2;
constexpr std::size_t kOdometerSize = 10;
constexpr std::size_t kFilterLlhSize = 26;
constexpr std::size_t kFilterQuatSize = 18;
constexpr std::size_t kFilterDcmSize = 38;
constexpr std::size_t kFilterStatusSize = 6;
constexpr std::size_t kDualAntennaSize = 17;
constexpr std::size_t kGnssLlhSize = 42;
constexpr std::size_t kGnssVelSize = 34;
constexpr std::size_t kFixInfoSize = 6;
// Offsets inside fields.
constexpr std::size_t kVec3fValidOffset = 12;
constexpr std::size_t kTimeWeekOffset = 8, kTimeValidOffset = 10;
constexpr std::size_t kOdoStdOffset = 4, kOdoValidOffset = 8;
constexpr std::size_t kLlhLonOffset = 8, kLlhHeightOffset = 16, kLlhValidOffset = 24;
constexpr std::size_t kQuatValidOffset = 16;
constexpr std::size_t kDcmValidOffset = 36;
constexpr std::size_t kDaHeadingOffset = 4, kDaStdOffset = 8, kDaFixOffset = 12, kDaValidOffset = 15;
constexpr std::size_t kGLlhHAccOffset = 32, kGLlhVAccOffset = 36, kGLlhValidOffset = 40;
constexpr std::size_t kGVelSpeedAccOffset = 24, kGVelValidOffset = 32;
constexpr std::size_t kFixNumSvOffset = 1, kFixFlagsOffset = 2, kFixValidOffset = 4;

struct TimeFields {
  bool gps = false;
  std::int64_t gps_ns = 0;
  bool ref = false;
  std::int64_t ref_ns = 0;
  std::int64_t dt_ns = -1;
};

std::int64_t gps_ns(const std::uint8_t* p) {
  return time::gps_ns_from_week_tow(static_cast<std::int32_t>(be16(p + kTimeWeekOffset)), f64(p));
}

// Shared time descriptors (digest §4.5). Returns true when `f` was one of them.
bool take_time(const FieldView& f, TimeFields& t, bool& error) {
  const std::uint8_t* d = f.data.data();
  switch (f.desc) {
    case shared::kGpsTimestamp:
      if (f.data.size() < kGpsTimeSize) { error = true; return true; }
      // Valid only with both TOW and week set (L6597; errata E13: set by 0x01,0x72).
      if ((be16(d + kTimeValidOffset) & shared::kGpsTimeValid) == shared::kGpsTimeValid &&
          std::isfinite(f64(d))) {
        t.gps = true;
        t.gps_ns = gps_ns(d);
      }
      return true;
    case shared::kReferenceTimestamp:
      if (f.data.size() < kRefTimeSize) { error = true; return true; }
      t.ref = true;  // monotonic, always valid (L6624)
      t.ref_ns = static_cast<std::int64_t>(be64(d) & 0x7FFF'FFFF'FFFF'FFFFull);
      return true;
    case shared::kReferenceTimeDelta:
      if (f.data.size() < kDeltaSize) { error = true; return true; }
      t.dt_ns = static_cast<std::int64_t>(be64(d) & 0x7FFF'FFFF'FFFF'FFFFull);
      return true;
    case shared::kDeltaTime: {
      if (f.data.size() < kDeltaSize) { error = true; return true; }
      const double s = f64(d);
      if (std::isfinite(s) && s >= 0.0 && s < 1e6 && t.dt_ns < 0) t.dt_ns = time::nanoseconds(s);
      return true;
    }
    default:
      return shared::is_shared(f.desc);
  }
}

}  // namespace

struct MipDecoder::PacketTime {
  std::int64_t ns = 0;
  TimeSource source = TimeSource::kUnknown;
  bool own = false;  // the packet carries its own time
  std::int64_t dt_ns = -1;
};

struct MipDecoder::PendingSolution {
  bool active = false;
  bool content = false;
  bool outputs_valid = true;
  std::uint8_t first_desc = 0;
  std::int64_t time_ns = 0;
  bool has_time = false;
  bool has_quat = false, has_euler = false, has_dcm = false, has_status = false;
  Eigen::Vector3d gravity_vehicle = Eigen::Vector3d::Zero();
  bool has_gravity = false;
  NavSolution s;
};

MipDecoder::MipDecoder(const DecoderOptions& options)
    : options_(options), clock_(options.clock), aiding_(&clock_), pending_(std::make_unique<PendingSolution>()) {
  last_time_source_.fill(TimeSource::kUnknown);
}

MipDecoder::~MipDecoder() = default;

void MipDecoder::feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) {
  framer_.feed(bytes, [this, &sink](const PacketView& p) { on_packet(p, sink); });
}

void MipDecoder::finish(DecodeSink& sink) {
  framer_.finish([this, &sink](const PacketView& p) { on_packet(p, sink); });
  flush_solution(sink);
}

// Resolves a packet's time from the fields gathered while walking it.
static void resolve(const TimeFields& t, time::ClockModel& clock, std::int64_t& last_ns, TimeSource& last_src,
                    std::int64_t& ns, TimeSource& src, bool& own) {
  if (t.gps && t.ref) clock.add_pair(t.ref_ns, t.gps_ns);
  own = true;
  if (t.gps) {
    ns = t.gps_ns;
    src = TimeSource::kGps;
  } else if (t.ref) {
    const auto mapped = clock.to_gps(t.ref_ns);
    ns = mapped ? *mapped : t.ref_ns;
    src = mapped ? TimeSource::kGps : TimeSource::kDeviceMonotonic;
  } else {
    // Fields without a timestamp belong with the set's preceding timestamp (L3994).
    own = false;
    ns = last_ns;
    src = last_src;
    return;
  }
  last_ns = ns;
  last_src = src;
}

void MipDecoder::on_packet(const PacketView& p, DecodeSink& sink) {
  if (sink.wants_frames()) emit_record(p, sink);
  switch (p.desc_set) {
    case set::kSensor: decode_sensor(p, sink); return;
    case set::kFilter: decode_filter(p, sink); return;
    case set::kGnss1: decode_gnss(p, options_.receiver_id_gnss1, sink); return;
    case set::kGnss2: decode_gnss(p, options_.receiver_id_gnss2, sink); return;
    case set::kGnssExternal: decode_gnss(p, options_.receiver_id_external, sink); return;
    case set::kAiding: decode_aiding(p, sink); return;
    case set::kGnssCorrections:
    case set::kSystem:
    case set::kBase:
    case set::k3dm:
    case set::kFilterCmd:
    case set::kGnssCmd:
      return;  // status and command traffic: framed and shown as records, no measurements
    default:
      ++framer_.counters().unknown_frames;
      return;
  }
}

void MipDecoder::decode_sensor(const PacketView& p, DecodeSink& sink) {
  TimeFields tf;
  bool error = false;
  const std::uint8_t* accel = nullptr;
  const std::uint8_t* gyro = nullptr;
  const std::uint8_t* dtheta = nullptr;
  const std::uint8_t* dvel = nullptr;
  const std::uint8_t* mag = nullptr;
  const std::uint8_t* pressure = nullptr;
  const std::uint8_t* odometer = nullptr;
  std::uint16_t overrange = 0;
  FieldWalker walk(p.payload);
  FieldView f;
  auto need = [&](std::size_t n) {
    if (f.data.size() >= n) return f.data.data();
    error = true;
    return static_cast<const std::uint8_t*>(nullptr);
  };
  while (walk.next(f)) {
    switch (f.desc) {
      case sensor::kScaledAccel: accel = need(kVec3fSize); break;
      case sensor::kScaledGyro: gyro = need(kVec3fSize); break;
      case sensor::kDeltaTheta: dtheta = need(kVec3fSize); break;
      case sensor::kDeltaVelocity: dvel = need(kVec3fSize); break;
      case sensor::kScaledMag: mag = need(kVec3fSize); break;
      case sensor::kScaledPressure: pressure = need(kPressureSize); break;
      case sensor::kOdometer: odometer = need(kOdometerSize); break;
      case sensor::kOverrange:
        if (const auto* d = need(kOverrangeSize)) overrange = be16(d);
        break;
      case sensor::kGpsTimestamp:
        // Legacy GPS timestamp: tow_valid (bit 3) and week_number_valid (bit 4) (L6490-6496).
        if (const auto* d = need(kGpsTimeSize)) {
          if ((be16(d + kTimeValidOffset) & sensor::kLegacyTimeValid) == sensor::kLegacyTimeValid && !tf.gps &&
              std::isfinite(f64(d))) {
            tf.gps = true;
            tf.gps_ns = gps_ns(d);
          }
        }
        break;
      default: take_time(f, tf, error); break;
    }
  }
  PacketTime t;
  resolve(tf, clock_, last_time_ns_[p.desc_set], last_time_source_[p.desc_set], t.ns, t.source, t.own);
  MeasurementHeader h;
  h.time_ns = t.ns;
  h.time_source = t.source;

  if ((dtheta && dvel) || accel || gyro) {
    ImuSample m;
    m.header = h;
    m.frame = SensorFrame::kVehicle;  // 0x80 vectors are in the vehicle frame (L6393, L2485)
    if (dtheta && dvel) {
      m.quantity = ImuQuantity::kIncrements;
      m.gyro = v3f(dtheta);
      m.accel = v3f(dvel) * kGravity_mps2;  // g*s -> m/s (errata E35)
      m.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
      m.dt_s = tf.dt_ns >= 0 ? time::seconds(tf.dt_ns) : 0.0;
    } else {
      m.quantity = ImuQuantity::kRates;
      if (gyro) {
        m.gyro = v3f(gyro);
        m.header.valid |= ImuSample::kValidGyro;
      }
      if (accel) {
        m.accel = v3f(accel) * kGravity_mps2;  // g -> m/s^2
        m.header.valid |= ImuSample::kValidAccel;
      }
      m.dt_s = tf.dt_ns >= 0 ? time::seconds(tf.dt_ns) : 0.0;
    }
    if (overrange & sensor::kOverAccelX) m.saturation |= ImuSample::kSatAccelX;
    if (overrange & sensor::kOverAccelY) m.saturation |= ImuSample::kSatAccelY;
    if (overrange & sensor::kOverAccelZ) m.saturation |= ImuSample::kSatAccelZ;
    if (overrange & sensor::kOverGyroX) m.saturation |= ImuSample::kSatGyroX;
    if (overrange & sensor::kOverGyroY) m.saturation |= ImuSample::kSatGyroY;
    if (overrange & sensor::kOverGyroZ) m.saturation |= ImuSample::kSatGyroZ;
    if (m.gyro.allFinite() && m.accel.allFinite()) sink.on_measurement(m);
    else error = true;  // NaN on the wire (e.g. the doc's 0x7FE5BF7F, L3957): never reaches the filter
  }
  if (mag) {
    Magnetometer m;
    m.header = h;
    m.header.valid = Magnetometer::kValidField;
    m.frame = SensorFrame::kVehicle;
    m.field_gauss = v3f(mag);
    if (m.field_gauss.allFinite()) sink.on_measurement(m);
    else error = true;
  }
  if (pressure) {
    Pressure m;
    m.header = h;
    m.header.valid = Pressure::kValidPressure;
    m.pressure_pa = f32(pressure) * kMbarToPa;
    if (std::isfinite(m.pressure_pa)) sink.on_measurement(m);
    else error = true;
  }
  if (odometer && (be16(odometer + kOdoValidOffset) & 1u)) {  // bit0: odometer configured (L6559)
    VehicleSpeed m;
    m.header = h;
    m.header.valid = VehicleSpeed::kValidSpeed;
    m.speed_mps = f32(odometer);
    m.is_signed = true;  // "can be negative for quadrature encoders" (L6553)
    m.speed_std_mps = f32(odometer + kOdoStdOffset);
    if (std::isfinite(m.speed_mps) && std::isfinite(m.speed_std_mps)) sink.on_measurement(m);
    else error = true;
  }
  if (error || walk.malformed()) ++framer_.counters().decode_errors;
}

void MipDecoder::flush_solution(DecodeSink& sink) {
  PendingSolution& ps = *pending_;
  if (ps.active && ps.content) {
    NavSolution& s = ps.s;
    // Attitude: quaternion preferred, then Euler, then DCM; the others derived from it.
    if (ps.has_quat) {
      if (!ps.has_euler) s.rpy_rad = rot::rpy_from_quat(s.q_nb);
    } else if (ps.has_euler) {
      s.q_nb = rot::quat_from_rpy(s.rpy_rad);
    }
    if (ps.has_gravity && (s.header.valid & NavSolution::kValidAttitude))
      s.gravity_ned_mps2 = s.q_nb * ps.gravity_vehicle;  // (0x82,0x13) is vehicle frame (L4445)
    if (s.header.valid & NavSolution::kValidAttitude) {
      // Yaw is absolute from AHRS on (digest §6.2); without a status it is taken as meaningful.
      if (!ps.has_status || s.mode == NavMode::kAhrs || s.mode == NavMode::kNavigation ||
          s.mode == NavMode::kDeadReckoning)
        s.header.valid |= NavSolution::kValidHeading;
    }
    if (!ps.outputs_valid) s.header.valid = 0;  // errata E16: solution error -> all outputs invalid
    sink.on_measurement(s);
  }
  ps.active = false;
}

void MipDecoder::decode_filter(const PacketView& p, DecodeSink& sink) {
  // First pass: the packet's own time decides whether it continues the pending epoch.
  TimeFields tf;
  bool error = false;
  {
    FieldWalker walk(p.payload);
    FieldView f;
    while (walk.next(f)) {
      if (f.desc == filter::kTimestamp && f.data.size() >= kGpsTimeSize) {
        if ((be16(f.data.data() + kTimeValidOffset) & filter::kValid) && std::isfinite(f64(f.data.data())) && !tf.gps) {
          tf.gps = true;
          tf.gps_ns = gps_ns(f.data.data());
        }
      } else {
        take_time(f, tf, error);
      }
    }
  }
  PacketTime t;
  resolve(tf, clock_, last_time_ns_[p.desc_set], last_time_source_[p.desc_set], t.ns, t.source, t.own);
  const std::uint8_t first = p.payload.size() >= kFieldHeaderSize ? p.payload[1] : 0;
  PendingSolution& ps = *pending_;
  // L3974-3996: a continuation repeats the leading shared timestamp (same time) or, without
  // one, is recognised by not starting with the epoch's first descriptor.
  const bool continues = ps.active && (t.own ? (ps.has_time && ps.time_ns == t.ns) : first != ps.first_desc);
  if (!continues) {
    flush_solution(sink);
    ps.active = true;
    ps.content = false;
    ps.outputs_valid = true;
    ps.first_desc = first;
    ps.time_ns = t.ns;
    ps.has_time = t.own;
    ps.has_quat = ps.has_euler = ps.has_dcm = ps.has_status = ps.has_gravity = false;
    ps.s = NavSolution{};
    ps.s.header.time_ns = t.ns;
    ps.s.header.time_source = t.source;
  }
  NavSolution& s = ps.s;
  FieldWalker walk(p.payload);
  FieldView f;
  auto need = [&](std::size_t n) {
    if (f.data.size() >= n) return f.data.data();
    error = true;
    return static_cast<const std::uint8_t*>(nullptr);
  };
  auto valid_vec = [&](const std::uint8_t* d) { return (be16(d + kVec3fValidOffset) & filter::kValid) != 0; };
  while (walk.next(f)) {
    const std::uint8_t* d = nullptr;
    switch (f.desc) {
      case filter::kLlh:
        if ((d = need(kFilterLlhSize)) && (be16(d + kLlhValidOffset) & filter::kValid)) {
          s.lat_rad = f64(d) * rot::kDegToRad;
          s.lon_rad = f64(d + kLlhLonOffset) * rot::kDegToRad;
          s.height_m = f64(d + kLlhHeightOffset);
          s.header.valid |= NavSolution::kValidPosition;
        }
        ps.content = true;
        break;
      case filter::kVelNed:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) {
          s.vel_ned_mps = v3f(d);
          s.header.valid |= NavSolution::kValidVelocity;
        }
        ps.content = true;
        break;
      case filter::kQuaternion:
        if ((d = need(kFilterQuatSize)) && (be16(d + kQuatValidOffset) & filter::kValid)) {
          // (w,x,y,z) with p_veh = q^-1 p_ned q (digest §6.1): q rotates vehicle into NED = q_nb.
          s.q_nb = Eigen::Quaterniond(f32(d), f32(d + 4), f32(d + 8), f32(d + 12));
          if (s.q_nb.norm() > 0.0) s.q_nb.normalize();
          ps.has_quat = true;
          s.header.valid |= NavSolution::kValidAttitude;
        }
        ps.content = true;
        break;
      case filter::kDcm:
        if ((d = need(kFilterDcmSize)) && (be16(d + kDcmValidOffset) & filter::kValid) && !ps.has_quat && !ps.has_euler) {
          Eigen::Matrix3d m;  // row-major, v_veh = M v_ned (digest §6.1) -> C_nb = M^T
          for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = f32(d + 4 * i);
          s.q_nb = Eigen::Quaterniond(Eigen::Matrix3d(m.transpose()));
          s.rpy_rad = rot::rpy_from_dcm(m.transpose());
          ps.has_dcm = true;
          s.header.valid |= NavSolution::kValidAttitude;
        }
        ps.content = true;
        break;
      case filter::kEuler:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) {
          s.rpy_rad = v3f(d);  // roll, pitch, yaw [rad], 3-2-1 (L4236)
          ps.has_euler = true;
          s.header.valid |= NavSolution::kValidAttitude;
        }
        ps.content = true;
        break;
      case filter::kGyroBias:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) {
          s.gyro_bias_rps = v3f(d);  // sensor frame (L2485)
          s.header.valid |= NavSolution::kValidBiases;
        }
        break;
      case filter::kAccelBias:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) {
          s.accel_bias_mps2 = v3f(d);
          s.header.valid |= NavSolution::kValidBiases;
        }
        break;
      case filter::kLlhUnc:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) {
          s.pos_std_ned_m = v3f(d);
          s.header.valid |= NavSolution::kValidPositionStd;
        }
        break;
      case filter::kVelUnc:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) {
          s.vel_std_ned_mps = v3f(d);
          s.header.valid |= NavSolution::kValidVelocityStd;
        }
        break;
      case filter::kEulerUnc:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) {
          s.att_std_rpy_rad = v3f(d);
          s.header.valid |= NavSolution::kValidAttitudeStd;
        }
        break;
      case filter::kGyroBiasUnc:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) s.gyro_bias_std_rps = v3f(d);
        break;
      case filter::kAccelBiasUnc:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) s.accel_bias_std_mps2 = v3f(d);
        break;
      case filter::kLinearAccel:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) s.linear_accel_mps2 = v3f(d);
        break;
      case filter::kCompAngularRate:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) s.angular_rate_rps = v3f(d);
        break;
      case filter::kGravity:
        if ((d = need(kVec3fValidSize)) && valid_vec(d)) {
          ps.gravity_vehicle = v3f(d);
          ps.has_gravity = true;
        }
        break;
      case filter::kStatus:
        if ((d = need(kFilterStatusSize))) {
          FilterStatusWord w{be16(d), be16(d + 2), be16(d + 4)};
          ps.outputs_valid = apply_status(w, s) && ps.outputs_valid;
          ps.has_status = true;
        }
        ps.content = true;
        break;
      case filter::kDualAntennaStatus:
        if ((d = need(kDualAntennaSize)) && (be16(d + kDaValidOffset) & filter::kValid)) {
          GnssHeading m;
          m.header.time_ns = t.ns;
          m.header.time_source = t.source;
          m.header.valid = GnssHeading::kValidHeading;
          m.heading_rad = f32(d + kDaHeadingOffset);
          m.heading_std_rad = f32(d + kDaStdOffset);
          const std::uint8_t fix = d[kDaFixOffset];
          m.fix = fix == filter::kDaFixFixed   ? GnssFixType::kRtkFixed
                  : fix == filter::kDaFixFloat ? GnssFixType::kRtkFloat
                                               : GnssFixType::kNone;
          if (std::isfinite(m.heading_rad) && std::isfinite(m.heading_std_rad)) sink.on_measurement(m);
          else error = true;
        }
        break;
      default:
        break;  // time fields (first pass) and fields without a core mapping
    }
  }
  if (!s.vel_ned_mps.allFinite() || !s.rpy_rad.allFinite() || !s.q_nb.coeffs().allFinite() ||
      !std::isfinite(s.lat_rad) || !std::isfinite(s.lon_rad) || !std::isfinite(s.height_m)) {
    ps.outputs_valid = false;  // NaN in the solution: never passed on as valid
    error = true;
  }
  if (error || walk.malformed()) ++framer_.counters().decode_errors;
}

void MipDecoder::decode_gnss(const PacketView& p, std::uint8_t receiver_id, DecodeSink& sink) {
  TimeFields tf;
  bool error = false;
  const std::uint8_t* llh = nullptr;
  const std::uint8_t* vel = nullptr;
  const std::uint8_t* fix = nullptr;
  FieldWalker walk(p.payload);
  FieldView f;
  auto need = [&](std::size_t n) {
    if (f.data.size() >= n) return f.data.data();
    error = true;
    return static_cast<const std::uint8_t*>(nullptr);
  };
  while (walk.next(f)) {
    switch (f.desc) {
      case gnss::kLlh: llh = need(kGnssLlhSize); break;
      case gnss::kVelNed: vel = need(kGnssVelSize); break;
      case gnss::kFixInfo: fix = need(kFixInfoSize); break;
      case gnss::kGpsTime:
        if (const auto* d = need(kGpsTimeSize)) {
          if ((be16(d + kTimeValidOffset) & gnss::kGpsTimeValid) == gnss::kGpsTimeValid && !tf.gps &&
              std::isfinite(f64(d))) {
            tf.gps = true;
            tf.gps_ns = gps_ns(d);
          }
        }
        break;
      default: take_time(f, tf, error); break;
    }
  }
  PacketTime t;
  resolve(tf, clock_, last_time_ns_[p.desc_set], last_time_source_[p.desc_set], t.ns, t.source, t.own);
  GnssFixType fix_type = GnssFixType::kNone;
  std::uint8_t num_sv = 0;
  if (fix) {
    const std::uint16_t valid = be16(fix + kFixValidOffset);
    const std::uint16_t flags = (valid & gnss::kFixValidFlags) ? be16(fix + kFixFlagsOffset) : 0;
    if (valid & gnss::kFixValidType) fix_type = fix_from_mip(fix[0], flags);
    if (valid & gnss::kFixValidNumSv) num_sv = fix[kFixNumSvOffset];
  }
  if (llh) {
    const std::uint16_t valid = be16(llh + kGLlhValidOffset);
    if (valid & gnss::kLlhValidLatLon) {
      GnssPosition m;
      m.header.time_ns = t.ns;
      m.header.time_source = t.source;
      m.header.valid = GnssPosition::kValidPosition;
      m.lat_rad = f64(llh) * rot::kDegToRad;
      m.lon_rad = f64(llh + kLlhLonOffset) * rot::kDegToRad;
      if (valid & gnss::kLlhValidHeight) {
        m.height_m = f64(llh + kLlhHeightOffset);
        m.header.valid |= GnssPosition::kValidHeight;
      }
      const std::uint16_t acc = gnss::kLlhValidHAcc | gnss::kLlhValidVAcc;
      if ((valid & acc) == acc) {
        // Horizontal accuracy is taken as the 1-sigma of each horizontal axis.
        const double h = f32(llh + kGLlhHAccOffset), v = f32(llh + kGLlhVAccOffset);
        m.cov_ned_m2 = Eigen::Vector3d(h * h, h * h, v * v).asDiagonal();
        m.header.valid |= GnssPosition::kValidCovariance;
      }
      m.fix = fix_type;
      m.num_sats = num_sv;
      m.receiver_id = receiver_id;
      if (std::isfinite(m.lat_rad) && std::isfinite(m.lon_rad) && std::isfinite(m.height_m) && m.cov_ned_m2.allFinite())
        sink.on_measurement(m);
      else
        error = true;
    }
  }
  if (vel) {
    const std::uint16_t valid = be16(vel + kGVelValidOffset);
    if (valid & gnss::kVelValidNed) {
      GnssVelocity m;
      m.header.time_ns = t.ns;
      m.header.time_source = t.source;
      m.header.valid = GnssVelocity::kValidVelocity;
      m.vel_ned_mps = v3f(vel);
      if (valid & gnss::kVelValidSpeedAcc) {
        const double s = f32(vel + kGVelSpeedAccOffset);
        m.cov_ned_m2ps2 = Eigen::Matrix3d::Identity() * (s * s);
        m.header.valid |= GnssVelocity::kValidCovariance;
      }
      m.fix = fix_type;
      m.receiver_id = receiver_id;
      if (m.vel_ned_mps.allFinite() && m.cov_ned_m2ps2.allFinite()) sink.on_measurement(m);
      else error = true;
    }
  }
  if (error || walk.malformed()) ++framer_.counters().decode_errors;
}

void MipDecoder::decode_aiding(const PacketView& p, DecodeSink& sink) {
  AidingResult result;
  aiding_.handle_payload(p.payload, result);
  for (const auto& m : result.measurements) sink.on_measurement(m);
  for (const auto& c : result.codes)
    if (c.second != ReplyCode::kAck) {
      ++framer_.counters().decode_errors;  // a command the device would have NACKed
      break;
    }
}

void MipDecoder::emit_record(const PacketView& p, DecodeSink& sink) {
  FrameRecord rec;
  build_frame_record(p, rec);
  sink.on_frame(rec);
}

}  // namespace navfuse::frontends::mip

// Filter set 0x82 -> NavSolution (device_solution) and GnssHeading (digest §4.2, §6).
#include "frontends/mip/decoder.hpp"

#include "core/rotation/rotation.hpp"
#include "frontends/mip/decoder_detail.hpp"
#include "frontends/mip/filter_status.hpp"

namespace navfuse::frontends::mip {

using namespace detail;

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

}  // namespace navfuse::frontends::mip

// GNSS sets 0x91/0x92/0x94 -> GnssPosition, GnssVelocity (digest §4.3).
#include "frontends/mip/decoder.hpp"

#include "core/rotation/rotation.hpp"
#include "frontends/mip/decoder_detail.hpp"
#include "frontends/mip/gnss_fix.hpp"

namespace navfuse::frontends::mip {

using namespace detail;

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

}  // namespace navfuse::frontends::mip

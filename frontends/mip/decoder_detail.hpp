// Internals shared by the MIP decoder's translation units (decoder*.cpp): big-endian loads,
// field sizes and offsets (digest §4, computed lengths of §4.7 minus the 2-byte field header),
// and packet time resolution. Not part of the public interface.
#pragma once

#include <bit>
#include <cmath>
#include <cstring>

#include "core/time/gps_time.hpp"
#include "frontends/mip/decoder.hpp"

namespace navfuse::frontends::mip {
namespace detail {

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
inline constexpr std::size_t kVec3fSize = 12;
inline constexpr std::size_t kVec3fValidSize = 14;        // vector3f + u16 valid (0x82 vectors)
inline constexpr std::size_t kGpsTimeSize = 12;           // f64 tow, u16 week, u16 valid
inline constexpr std::size_t kRefTimeSize = 8;            // u64 ns
inline constexpr std::size_t kDeltaSize = 8;              // u64 ns or f64 s
inline constexpr std::size_t kPressureSize = 4;
inline constexpr std::size_t kOverrangeSize = 2;
inline constexpr std::size_t kOdometerSize = 10;
inline constexpr std::size_t kFilterLlhSize = 26;
inline constexpr std::size_t kFilterQuatSize = 18;
inline constexpr std::size_t kFilterDcmSize = 38;
inline constexpr std::size_t kFilterStatusSize = 6;
inline constexpr std::size_t kDualAntennaSize = 17;
inline constexpr std::size_t kGnssLlhSize = 42;
inline constexpr std::size_t kGnssVelSize = 34;
inline constexpr std::size_t kFixInfoSize = 6;
// Offsets inside fields.
inline constexpr std::size_t kVec3fValidOffset = 12;
inline constexpr std::size_t kTimeWeekOffset = 8, kTimeValidOffset = 10;
inline constexpr std::size_t kOdoStdOffset = 4, kOdoValidOffset = 8;
inline constexpr std::size_t kLlhLonOffset = 8, kLlhHeightOffset = 16, kLlhValidOffset = 24;
inline constexpr std::size_t kQuatValidOffset = 16;
inline constexpr std::size_t kDcmValidOffset = 36;
inline constexpr std::size_t kDaHeadingOffset = 4, kDaStdOffset = 8, kDaFixOffset = 12, kDaValidOffset = 15;
inline constexpr std::size_t kGLlhHAccOffset = 32, kGLlhVAccOffset = 36, kGLlhValidOffset = 40;
inline constexpr std::size_t kGVelSpeedAccOffset = 24, kGVelValidOffset = 32;
inline constexpr std::size_t kFixNumSvOffset = 1, kFixFlagsOffset = 2, kFixValidOffset = 4;

struct TimeFields {
  bool gps = false;
  std::int64_t gps_ns = 0;
  bool ref = false;
  std::int64_t ref_ns = 0;
  std::int64_t dt_ns = -1;
};

inline std::int64_t gps_ns(const std::uint8_t* p) {
  return time::gps_ns_from_week_tow(static_cast<std::int32_t>(be16(p + kTimeWeekOffset)), f64(p));
}

// Shared time descriptors (digest §4.5). Returns true when `f` was one of them.
inline bool take_time(const FieldView& f, TimeFields& t, bool& error) {
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


// Resolves a packet's time from the fields gathered while walking it.
inline void resolve(const TimeFields& t, time::ClockModel& clock, std::int64_t& last_ns, TimeSource& last_src,
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

}  // namespace detail

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

}  // namespace navfuse::frontends::mip

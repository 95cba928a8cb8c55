#include "frontends/rtklib/to_core.hpp"

#include <charconv>
#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/geodesy/geoid.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/common/text_fields.hpp"

namespace navfuse::frontends::rtklib {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr std::int64_t kJstMinusUtcNs = 9 * 3600 * time::kNsPerSecond;
// An ECEF x beyond this many metres cannot be a latitude/longitude in degrees or dms.
constexpr double kEcefThresholdM = 360.0;
// Dates a GNSS solution can have: from the GPS epoch to week 10000 (year 2171), well inside the
// int64 nanoseconds of core/time.
constexpr int kFirstYear = 1980, kLastYear = 2170;
constexpr int kLastWeek = 10000;

std::optional<int> parse_int(std::string_view s) {
  int v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

// "yyyy/mm/dd" "hh:mm:ss.sss" -> the calendar fields.
std::optional<time::UtcDateTime> parse_calendar(std::string_view date, std::string_view clock) {
  if (date.size() != 10 || date[4] != '/' || date[7] != '/' || clock.size() < 8 || clock[2] != ':' || clock[5] != ':') {
    return std::nullopt;
  }
  const auto y = parse_int(date.substr(0, 4)), mo = parse_int(date.substr(5, 2)), d = parse_int(date.substr(8, 2));
  const auto h = parse_int(clock.substr(0, 2)), mi = parse_int(clock.substr(3, 2));
  const auto s = text::parse_number(clock.substr(6));
  if (!y || !mo || !d || !h || !mi || !s || *y < kFirstYear || *y > kLastYear || *h > 23 || *mi > 59 || *s < 0.0 || *s >= 61.0) return std::nullopt;
  return time::UtcDateTime{*y, *mo, *d, *h, *mi, *s};
}

std::optional<std::int64_t> parse_time(std::string_view a, std::string_view b, TimeSystem system) {
  // Both forms read first as a time on the file's own scale, expressed as GPS-epoch ns.
  std::int64_t scale_ns = 0;
  if (a.find('/') != std::string_view::npos) {
    const auto cal = parse_calendar(a, b);
    if (!cal) return std::nullopt;
    const auto unix_ns = time::unix_ns_from_utc(*cal);
    if (!unix_ns) return std::nullopt;
    scale_ns = *unix_ns - time::kGpsEpochUnixS * time::kNsPerSecond;
  } else {
    const auto week = parse_int(a);
    const auto tow = text::parse_number(b);
    if (!week || !tow || *week < 0 || *week > kLastWeek || *tow < 0.0 || *tow >= time::kSecondsPerWeek) return std::nullopt;
    scale_ns = time::gps_ns_from_week_tow(*week, *tow);
  }
  switch (system) {
    case TimeSystem::kGpst:
      return scale_ns;
    case TimeSystem::kUtc:
      return time::gps_ns_from_unix_ns(scale_ns + time::kGpsEpochUnixS * time::kNsPerSecond);
    case TimeSystem::kJst:
      return time::gps_ns_from_unix_ns(scale_ns - kJstMinusUtcNs + time::kGpsEpochUnixS * time::kNsPerSecond);
  }
  return std::nullopt;
}

// "-105" "08" "49.79940" -> degrees; the sign is read from the text ("-0 30 00" is south/west).
std::optional<double> parse_dms(std::string_view d, std::string_view m, std::string_view s) {
  const auto dv = text::parse_number(d), mv = text::parse_number(m), sv = text::parse_number(s);
  if (!dv || !mv || !sv || *mv < 0.0 || *mv >= 60.0 || *sv < 0.0 || *sv >= 60.0) return std::nullopt;
  const double magnitude = std::abs(*dv) + *mv / 60.0 + *sv / 3600.0;
  return d.starts_with('-') ? -magnitude : magnitude;
}

// Symmetric covariance from three std devs and three signed square-rooted covariances
// (pairs 01, 12, 20: ne eu un, or xy yz zx).
std::optional<Eigen::Matrix3d> covariance(const double (&sd)[3], const double (&sdc)[3]) {
  Eigen::Matrix3d p;
  for (int i = 0; i < 3; ++i) {
    if (sd[i] < 0.0) return std::nullopt;
    p(i, i) = sd[i] * sd[i];
  }
  const auto cov = [](double s) { return std::copysign(s * s, s); };
  p(0, 1) = p(1, 0) = cov(sdc[0]);
  p(1, 2) = p(2, 1) = cov(sdc[1]);
  p(2, 0) = p(0, 2) = cov(sdc[2]);
  return p;
}

// North-east-up -> north-east-down for a vector (v) and a covariance (P).
const Eigen::Matrix3d kNeuToNed = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();

}  // namespace

GnssFixType fix_from_quality(int q) {
  switch (q) {
    case 1: return GnssFixType::kRtkFixed;
    case 2: return GnssFixType::kRtkFloat;
    case 3: return GnssFixType::kSbas;
    case 4: return GnssFixType::kDgnss;
    case 5: return GnssFixType::kFix3D;
    case 6: return GnssFixType::kPpp;
    case 7: return GnssFixType::kDeadReckoning;
    default: return GnssFixType::kNone;
  }
}

std::optional<PosRecord> parse_record(std::string_view line, const PosLayout& header_layout) {
  if (header_layout.coords == Coordinates::kUnsupported || !header_layout.wgs84) return std::nullopt;
  std::string_view f[48];
  const std::size_t n = std::min(text::split_fields(line, f), std::size(f));
  if (n < 5) return std::nullopt;
  PosRecord r;
  const auto t = parse_time(f[0], f[1], header_layout.time);
  if (!t) return std::nullopt;
  r.time_ns = *t;

  // Without a header the coordinate form is told from the first coordinate's size.
  PosLayout layout = header_layout;
  if (!layout.from_header) {
    const auto x = text::parse_number(f[2]);
    if (x && std::abs(*x) > kEcefThresholdM) layout = default_layout(Coordinates::kEcef);
  }
  const std::size_t coord_fields = layout.coords == Coordinates::kLlhDms ? 7 : 3;  // d m s, d m s, h
  const std::size_t first = 2 + coord_fields;
  if (n < first) return std::nullopt;
  const std::size_t named = n - first;
  const auto value = [&](int column) -> std::optional<double> {
    if (column < 0 || static_cast<std::size_t>(column) >= named) return std::nullopt;
    return text::parse_number(f[first + static_cast<std::size_t>(column)]);
  };
  const auto q = value(layout.columns.q);
  const auto ns = value(layout.columns.ns);
  if (!q || !ns || *q != std::floor(*q) || *q < 0 || *q > 7 || *ns < 0 || *ns > 255) return std::nullopt;
  r.quality = static_cast<int>(*q);
  r.fix = fix_from_quality(r.quality);
  r.num_sats = static_cast<int>(*ns);

  // Every named column the layout has must be a number on this line.
  const auto triplet = [&](const int (&cols)[3], double (&out)[3]) -> int {  // 1 present, 0 absent, -1 damaged
    if (cols[0] < 0 || cols[1] < 0 || cols[2] < 0) return 0;
    // Without a header the velocity columns of the default form are optional.
    if (!layout.from_header && static_cast<std::size_t>(cols[0]) >= named) return 0;
    for (int k = 0; k < 3; ++k) {
      const auto v = value(cols[k]);
      if (!v) return -1;
      out[k] = *v;
    }
    return 1;
  };
  double sd[3] = {}, sdc[3] = {}, vel[3] = {}, sdv[3] = {}, sdvc[3] = {};
  const int has_sd = triplet(layout.columns.sd, sd);
  const int has_sdc = triplet(layout.columns.sdc, sdc);
  const int has_vel = triplet(layout.columns.vel, vel);
  const int has_sdv = triplet(layout.columns.sdv, sdv);
  const int has_sdvc = triplet(layout.columns.sdvc, sdvc);
  if (has_sd < 0 || has_sdc < 0 || has_vel < 0 || has_sdv < 0 || has_sdvc < 0) return std::nullopt;

  Eigen::Matrix3d to_ned = kNeuToNed;  // rotation of the file's axes into NED
  if (layout.coords == Coordinates::kEcef) {
    Eigen::Vector3d xyz;
    for (int k = 0; k < 3; ++k) {
      const auto v = text::parse_number(f[2 + static_cast<std::size_t>(k)]);
      if (!v) return std::nullopt;
      xyz[k] = *v;
    }
    if (xyz.norm() < 1.0e6) return std::nullopt;  // not on (or above) the earth
    const geo::Llh llh = geo::llh_from_ecef(xyz);
    r.lat_rad = llh.lat_rad;
    r.lon_rad = llh.lon_rad;
    r.height_m = llh.height_m;
    to_ned = geo::rot_ecef_from_ned(r.lat_rad, r.lon_rad).transpose();
  } else {
    std::optional<double> lat, lon, h;
    if (layout.coords == Coordinates::kLlhDms) {
      lat = parse_dms(f[2], f[3], f[4]);
      lon = parse_dms(f[5], f[6], f[7]);
      h = text::parse_number(f[8]);
    } else {
      lat = text::parse_number(f[2]);
      lon = text::parse_number(f[3]);
      h = text::parse_number(f[4]);
    }
    if (!lat || !lon || !h || std::abs(*lat) > 90.0 || std::abs(*lon) > 360.0) return std::nullopt;
    r.lat_rad = *lat * kDegToRad;
    r.lon_rad = *lon * kDegToRad;
    r.height_m = *h;
    if (layout.geoid_height) {
      const auto n_m = geo::egm96_undulation_m(r.lat_rad, r.lon_rad);
      r.has_height = n_m.has_value();
      if (n_m) r.height_m += *n_m;
    }
  }

  // A covariance in the file's axes, rotated into NED; false for a negative std dev.
  const auto noise = [&](const double (&sdev)[3], const double (&sqcov)[3], bool with_cov, bool& valid,
                         Eigen::Matrix3d& out) {
    const double zero[3] = {0.0, 0.0, 0.0};
    const auto p = covariance(sdev, with_cov ? sqcov : zero);
    if (!p) return false;
    valid = sdev[0] > 0.0 || sdev[1] > 0.0 || sdev[2] > 0.0;
    out = to_ned * *p * to_ned.transpose();
    return true;
  };
  if (has_sd > 0 && !noise(sd, sdc, has_sdc > 0, r.has_covariance, r.cov_ned_m2)) return std::nullopt;
  if (has_vel > 0) {
    r.has_velocity = true;
    r.vel_ned_mps = to_ned * Eigen::Vector3d(vel[0], vel[1], vel[2]);
    if (has_sdv > 0 && !noise(sdv, sdvc, has_sdvc > 0, r.has_velocity_covariance, r.vel_cov_ned_m2ps2)) {
      return std::nullopt;
    }
  }
  return r;
}

void to_core(const PosRecord& r, DecodeSink& sink) {
  GnssPosition p;
  p.header.time_ns = r.time_ns;
  p.header.time_source = TimeSource::kGps;
  p.header.valid = GnssPosition::kValidPosition | (r.has_height ? GnssPosition::kValidHeight : 0u) |
                   (r.has_covariance ? GnssPosition::kValidCovariance : 0u);
  p.lat_rad = r.lat_rad;
  p.lon_rad = r.lon_rad;
  p.height_m = r.height_m;
  p.cov_ned_m2 = r.cov_ned_m2;
  p.fix = r.fix;
  p.num_sats = static_cast<std::uint8_t>(r.num_sats);
  sink.on_measurement(p);
  if (!r.has_velocity) return;
  GnssVelocity v;
  v.header.time_ns = r.time_ns;
  v.header.time_source = TimeSource::kGps;
  v.header.valid = GnssVelocity::kValidVelocity | (r.has_velocity_covariance ? GnssVelocity::kValidCovariance : 0u);
  v.vel_ned_mps = r.vel_ned_mps;
  v.cov_ned_m2ps2 = r.vel_cov_ned_m2ps2;
  v.fix = r.fix;
  sink.on_measurement(v);
}

FrameRecord to_frame_record(const PosRecord& r, std::uint64_t offset) {
  FrameRecord f;
  f.protocol = "rtklib";
  f.name = "solution";
  f.offset = offset;
  f.fields = {{"time_gps_ns", static_cast<std::int64_t>(r.time_ns)},
              {"q", static_cast<std::int64_t>(r.quality)},
              {"ns", static_cast<std::int64_t>(r.num_sats)},
              {"lat_deg", r.lat_rad / kDegToRad},
              {"lon_deg", r.lon_rad / kDegToRad},
              {"height_m", r.height_m},
              {"sdn_m", std::sqrt(r.cov_ned_m2(0, 0))},
              {"sde_m", std::sqrt(r.cov_ned_m2(1, 1))},
              {"sdd_m", std::sqrt(r.cov_ned_m2(2, 2))}};
  if (r.has_velocity) {
    f.fields.emplace_back("vn_mps", r.vel_ned_mps.x());
    f.fields.emplace_back("ve_mps", r.vel_ned_mps.y());
    f.fields.emplace_back("vd_mps", r.vel_ned_mps.z());
  }
  return f;
}

}  // namespace navfuse::frontends::rtklib

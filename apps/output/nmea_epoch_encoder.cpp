#include "apps/output/nmea_epoch_encoder.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::apps {
namespace nmea = frontends::nmea;
namespace {

constexpr nmea::Talker kTalker{'G', 'N'};  // a multi-constellation solution (NMEA 0183 v4 "GN")
// Decimals: minutes to 1e-6 (2 mm), heights and speeds to mm, angles to 0.01 deg.
constexpr int kMinuteDecimals = 6;

bool has(const NavSolution& s, std::uint32_t bit) { return (s.header.valid & bit) != 0; }

// GGA quality (NMEA 0183: 1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK float, 6 estimated / dead reckoning).
std::uint32_t gga_quality(const NavSolution& s) {
  if (!has(s, NavSolution::kValidPosition)) return 0;
  if (s.mode == NavMode::kDeadReckoning) return 6;
  switch (s.gnss_fix) {
    case GnssFixType::kRtkFixed: return 4;
    case GnssFixType::kRtkFloat: return 5;
    case GnssFixType::kDgnss:
    case GnssFixType::kSbas:
    case GnssFixType::kPpp: return 2;
    default: return 1;
  }
}

// RMC mode indicator (NMEA 0183 v2.3: A autonomous, D differential, E estimated, N not valid).
char rmc_mode(std::uint32_t quality) {
  switch (quality) {
    case 0: return 'N';
    case 6: return 'E';
    case 1: return 'A';
    default: return 'D';
  }
}

double degrees_0_360(double rad) {
  const double deg = std::fmod(rad * rot::kRadToDeg, 360.0);
  return deg < 0.0 ? deg + 360.0 : deg;
}

struct UtcFields {
  std::optional<nmea::TimeOfDay> time;
  std::optional<nmea::Date> date;
};

UtcFields utc_fields(const NavSolution& s) {
  UtcFields f;
  if (s.header.time_source == TimeSource::kGps) {
    const std::int64_t unix_ns = time::unix_ns_from_gps_ns(s.header.time_ns);
    const std::int64_t day_ns = ((unix_ns % nmea::kNsPerDay) + nmea::kNsPerDay) % nmea::kNsPerDay;
    f.time = nmea::TimeOfDay{day_ns, 2};
    const time::UtcDateTime utc = time::utc_from_unix_ns(unix_ns);
    f.date = nmea::Date{utc.year, utc.month, utc.day};
  }
  return f;
}

nmea::Gga make_gga(const NavSolution& s, std::uint8_t num_sats, const std::optional<nmea::TimeOfDay>& time) {
  const bool position = has(s, NavSolution::kValidPosition);
  nmea::Gga gga;
  gga.talker = kTalker;
  gga.time = time;
  gga.quality = gga_quality(s);
  if (position) {
    gga.lat = nmea::LatLonField{s.lat_rad * rot::kRadToDeg, kMinuteDecimals};
    gga.lon = nmea::LatLonField{s.lon_rad * rot::kRadToDeg, kMinuteDecimals};
    // Altitude above mean sea level plus the geoid separation (NMEA GGA fields 9 and 11); without
    // a geoid model the ellipsoidal height with an empty separation.
    const bool geoid = has(s, NavSolution::kValidUndulation);
    gga.height_m = nmea::Real{s.height_m - (geoid ? s.undulation_m : 0.0), 3};
    if (geoid) gga.geoid_separation_m = nmea::Real{s.undulation_m, 3};
    if (num_sats > 0) gga.num_sats = nmea::Count{num_sats, 2};
  }
  gga.height_unit = position;
  return gga;
}

}  // namespace

void append_gga_sentence(const NavSolution& s, std::uint8_t num_sats, std::vector<std::uint8_t>& out) {
  nmea::encode(make_gga(s, num_sats, utc_fields(s).time), out);
}

void append_nmea_sentences(const NavSolution& s, std::uint8_t num_sats, std::vector<std::uint8_t>& out) {
  const auto [time, date] = utc_fields(s);
  const bool position = has(s, NavSolution::kValidPosition);
  const nmea::Gga gga = make_gga(s, num_sats, time);
  nmea::encode(gga, out);

  nmea::Rmc rmc;
  rmc.talker = kTalker;
  rmc.dialect = nmea::Dialect::kH30;  // no navStatus field: the NMEA 0183 v2.3 layout
  rmc.time = time;
  rmc.date = date;
  rmc.status = position ? 'A' : 'V';
  if (position) {
    rmc.lat = gga.lat;
    rmc.lon = gga.lon;
  }
  if (has(s, NavSolution::kValidVelocity)) {
    const double speed = s.vel_ned_mps.head<2>().norm();
    rmc.speed_knots = nmea::Real{speed / nmea::kMetresPerSecondPerKnot, 3};
    rmc.course_deg = nmea::Real{degrees_0_360(std::atan2(s.vel_ned_mps.y(), s.vel_ned_mps.x())), 2};
  }
  rmc.mode = rmc_mode(gga.quality);
  nmea::encode(rmc, out);

  if (has(s, NavSolution::kValidAttitude) && has(s, NavSolution::kValidHeading)) {
    nmea::Hdt hdt;
    hdt.talker = kTalker;
    hdt.heading_deg = nmea::Real{degrees_0_360(s.rpy_rad.z()), 2};
    nmea::encode(hdt, out);
  }
}

void NmeaEpochEncoder::append(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) {
  if (!epoch.pose_due) return;
  const std::int64_t slot_ns = static_cast<std::int64_t>(std::llround(1e9 / kNmeaRate_hz));
  const std::int64_t t = epoch.solution.header.time_ns;
  const std::int64_t slot = t >= 0 ? t / slot_ns : (t - slot_ns + 1) / slot_ns;
  if (slot == last_slot_) return;
  last_slot_ = slot;
  append_nmea_sentences(epoch.solution, epoch.num_sats, out);
}

}  // namespace navfuse::apps

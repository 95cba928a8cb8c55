#include "frontends/unicore/utc_clock.hpp"

#include <cmath>

#include "core/time/gps_time.hpp"

namespace navfuse::frontends::unicore {
namespace {

using time::kNsPerSecond;
using time::kNsPerWeek;
using nmea::kNsPerDay;

constexpr std::int64_t kSecondsPerDay = 86'400;
// GLONASS time is UTC(SU) + 3 h (GLONASS ICD 5.1 §3.3.3; digest §4.7 checks it on the example).
constexpr std::int64_t kGlonassMinusUtcS = 3 * 3600;
// BDT = GPST - 14 s (BDS ICD; digest §4.7: BDT = GPST - 14 s in the NAVTIME example).
constexpr std::int64_t kGpsMinusBdsS = 14;
// NAVPOS/NAVVEL system mask bits (L1288, as printed).
constexpr std::uint32_t kSystemGps = 1u << 0;
constexpr std::uint32_t kSystemBds = 1u << 2;
constexpr std::uint32_t kSystemGal = 1u << 5;
// Plausible GPS - UTC; anything else derived from a corrupt sentence is ignored.
constexpr int kMaxLeapS = 100;
// The LSF week number carries only its low 8 bits (L1427-L1434); IS-GPS-200 §20.3.3.5.2.4
// resolves it to within +-128 weeks of the current week (the wrap the spec omits, digest §11 item 26).
constexpr std::int32_t kWnlsfModulus = 256;
constexpr std::int64_t kUnixEpochToGpsNs = time::kGpsEpochUnixS * kNsPerSecond;

// The instance of `value + k * period` nearest `reference`.
std::int64_t nearest(std::int64_t value, std::int64_t period, std::int64_t reference) {
  std::int64_t k = (reference - value) / period;
  std::int64_t best = value + k * period;
  for (std::int64_t d : {-1, 1}) {
    const std::int64_t c = value + (k + d) * period;
    if (std::llabs(c - reference) < std::llabs(best - reference)) best = c;
  }
  return best;
}

}  // namespace

int UtcClock::gps_minus_utc_s(std::int64_t gps_ns) const {
  if (device_leap_s_) {
    if (leap_event_gps_ns_ && gps_ns >= *leap_event_gps_ns_) return leap_after_event_s_;
    return *device_leap_s_;
  }
  return time::gps_minus_utc_s_at_gps(gps_ns);
}

std::optional<std::int64_t> UtcClock::on_navtime(const Navtime& m) {
  if (m.gps_quality < kTimeQualityCoarse) return std::nullopt;
  const std::int64_t gps_ns =
      time::gps_ns_from_week_tow(static_cast<std::int32_t>(m.gps_week), m.gps_tow_s.value);
  if (m.glo_quality >= kTimeQualityCoarse && !leap_event_gps_ns_) {
    // GPS seconds of day minus UTC seconds of day (GLONASS time of day - 3 h) is GPS - UTC.
    const double gps_sod = std::fmod(m.gps_tow_s.value, static_cast<double>(kSecondsPerDay));
    const double utc_sod = m.glo_time_of_day_s.value - static_cast<double>(kGlonassMinusUtcS);
    auto leap = static_cast<std::int64_t>(std::llround(gps_sod - utc_sod));
    leap = ((leap % kSecondsPerDay) + kSecondsPerDay) % kSecondsPerDay;
    if (leap > kSecondsPerDay / 2) leap -= kSecondsPerDay;
    if (leap >= 0 && leap <= kMaxLeapS) device_leap_s_ = static_cast<int>(leap);
  }
  set_anchor(gps_ns);
  return gps_ns;
}

void UtcClock::on_lsf(const Lsf& m) {
  if (m.system != kLsfSystemGps || m.flag != 1 || m.tls_s > static_cast<std::uint32_t>(kMaxLeapS) ||
      m.tlsf_s > static_cast<std::uint32_t>(kMaxLeapS)) {
    return;
  }
  device_leap_s_ = static_cast<int>(m.tls_s);
  leap_after_event_s_ = static_cast<int>(m.tlsf_s);
  leap_event_gps_ns_.reset();
  if (anchor_gps_ns_ && m.tls_s != m.tlsf_s) {
    const std::int32_t week = time::week_tow_from_gps_ns(*anchor_gps_ns_).week;
    // STEP1/STEP2 of L1429-L1434, plus the +-128-week wrap.
    std::int32_t wn = (week & ~(kWnlsfModulus - 1)) + static_cast<std::int32_t>(m.wnlsf % kWnlsfModulus);
    if (wn - week > kWnlsfModulus / 2) wn -= kWnlsfModulus;
    if (week - wn > kWnlsfModulus / 2) wn += kWnlsfModulus;
    // The leap second is inserted at the end of day DN (1 = Sunday for GPS, L1436): the new
    // offset applies from the start of day DN + 1, on the UTC scale (hence + TLS in GPS time).
    leap_event_gps_ns_ = static_cast<std::int64_t>(wn) * kNsPerWeek +
                         static_cast<std::int64_t>(m.dn) * kNsPerDay +
                         static_cast<std::int64_t>(m.tls_s) * kNsPerSecond;
  }
}

std::optional<std::int64_t> UtcClock::from_utc(const nmea::Date& date, const nmea::TimeOfDay& tod) {
  if (!cache_valid_ || date.year != cached_date_.year || date.month != cached_date_.month ||
      date.day != cached_date_.day) {
    const auto midnight = time::unix_ns_from_utc(time::UtcDateTime{date.year, date.month, date.day, 0, 0, 0.0});
    if (!midnight) return std::nullopt;
    cached_date_ = date;
    cached_midnight_unix_ns_ = *midnight;
    cache_valid_ = true;
  }
  const std::int64_t unix_ns = cached_midnight_unix_ns_ + tod.ns;
  // Leap lookup at the approximate GPS time (the table changes only at midnight UTC).
  const std::int64_t approx_gps = unix_ns - kUnixEpochToGpsNs;
  const std::int64_t gps_ns =
      approx_gps + static_cast<std::int64_t>(gps_minus_utc_s(approx_gps)) * kNsPerSecond;
  set_anchor(gps_ns);
  return gps_ns;
}

std::optional<std::int64_t> UtcClock::from_time_of_day(const nmea::TimeOfDay& tod) {
  if (!anchor_gps_ns_) return std::nullopt;
  const std::int64_t leap_ns = static_cast<std::int64_t>(gps_minus_utc_s(*anchor_gps_ns_)) * kNsPerSecond;
  // Work in "UTC ns since the GPS epoch": the anchor's UTC day, nearest instance of tod.
  const std::int64_t anchor_utc = *anchor_gps_ns_ - leap_ns;
  const std::int64_t day_start = anchor_utc - (((anchor_utc % kNsPerDay) + kNsPerDay) % kNsPerDay);
  const std::int64_t utc = nearest(day_start + tod.ns, kNsPerDay, anchor_utc);
  const std::int64_t gps_ns = utc + leap_ns;
  set_anchor(gps_ns);
  return gps_ns;
}

std::optional<std::int64_t> UtcClock::from_ms_of_week(std::uint32_t ms, std::uint32_t system_mask) {
  if (!anchor_gps_ns_) return std::nullopt;
  std::int64_t offset_ns = 0;
  if ((system_mask & (kSystemGps | kSystemGal)) == 0) {
    if ((system_mask & kSystemBds) == 0) return std::nullopt;  // GLONASS-only or no system
    offset_ns = kGpsMinusBdsS * kNsPerSecond;
  }
  const std::int64_t tow_ns = static_cast<std::int64_t>(ms) * 1'000'000 + offset_ns;
  const std::int64_t gps_ns = nearest(tow_ns, kNsPerWeek, *anchor_gps_ns_);
  set_anchor(gps_ns);
  return gps_ns;
}

}  // namespace navfuse::frontends::unicore

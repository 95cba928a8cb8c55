// Puts the UM220's time stamps on GPS time (DESIGN.md: measurements carry GPS ns).
//
// The device stamps its sentences in three ways (digest §12 "Timestamps"):
//   * full UTC date and time: GYOACC (when resolved), RMC, ZDA;
//   * UTC time of day only: GGA, GLL, GST, NAVACC, NAVATT;
//   * milliseconds of the GNSS week: NAVPOS, NAVVEL (unit inferred, digest §11 item 23);
// and NAVTIME gives GPS week + seconds of week outright. The clock keeps an anchor (the latest
// fully resolved instant) and resolves a time of day or a millisecond of week to the instance
// nearest that anchor, so day and week rollovers need no special case.
//
// Policy for stamps that need a date (issue #6): until the first full time has been seen, such
// stamps cannot be resolved and the decoder DROPS the measurement, counting it under
// DropCounts::no_date. Nothing is emitted with an unknown time.
//
// GPS - UTC: the value the device reports wins (LSF for GPS, L1392-L1438, or the GLONASS time of
// day in NAVTIME, which runs at UTC + 3 h); without one, the core leap-second table.
#pragma once

#include <cstdint>
#include <optional>

#include "frontends/nmea/utc_fields.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {

class UtcClock {
 public:
  // Full-time sources: they set the anchor.
  // NAVTIME: GPS week/TOW when its quality is at least coarse; also derives GPS-UTC from the
  // GLONASS time of day when that is valid. Returns the GPS time, or nullopt if unusable.
  std::optional<std::int64_t> on_navtime(const Navtime& m);
  // LSF output for GPS with flag 1: GPS-UTC before / after the announced leap second.
  void on_lsf(const Lsf& m);
  // UTC date + time of day (RMC, ZDA, GYOACC): GPS ns, and sets the anchor.
  std::optional<std::int64_t> from_utc(const nmea::Date& date, const nmea::TimeOfDay& tod);

  // Time-of-day-only and week-relative stamps, resolved against the anchor (and advancing it).
  std::optional<std::int64_t> from_time_of_day(const nmea::TimeOfDay& tod);
  // NAVPOS/NAVVEL time; `system_mask` picks the time scale (GPS, or BDS = GPS - 14 s when BDS
  // is the only system, L1287). GLONASS-only solutions (Moscow time) are not resolved.
  std::optional<std::int64_t> from_ms_of_week(std::uint32_t ms, std::uint32_t system_mask);

  bool has_anchor() const { return anchor_gps_ns_.has_value(); }
  // GPS - UTC in force at `gps_ns`.
  int gps_minus_utc_s(std::int64_t gps_ns) const;
  // Whether GPS - UTC came from the device (LSF / NAVTIME) rather than the table.
  bool leap_from_device() const { return device_leap_s_.has_value(); }

 private:
  // A corrupt sentence can carry any week or date: only a GPS time between the GPS epoch and
  // 200 years later becomes the anchor, so resolving against it can never overflow int64 ns
  // (found by the fuzzer under UBSan).
  void set_anchor(std::int64_t gps_ns) {
    constexpr std::int64_t kMaxPlausibleGpsNs = 200LL * 365 * 86400 * 1'000'000'000LL;
    if (gps_ns >= 0 && gps_ns < kMaxPlausibleGpsNs) anchor_gps_ns_ = gps_ns;
  }

  std::optional<std::int64_t> anchor_gps_ns_;
  std::optional<int> device_leap_s_;
  // Leap-second event announced by LSF: GPS time from which tlsf applies.
  std::optional<std::int64_t> leap_event_gps_ns_;
  int leap_after_event_s_ = 0;
  // Cache of the last date's Unix midnight (GYOACC repeats the same date at 10 Hz).
  nmea::Date cached_date_{};
  std::int64_t cached_midnight_unix_ns_ = 0;
  bool cache_valid_ = false;
};

}  // namespace navfuse::frontends::unicore

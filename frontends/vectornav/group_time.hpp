// Time group (group bit 1; ICD Table 2.4, L786-909; digest §5.2) and the TimeUtc layout it
// shares with the GNSS groups.
#pragma once

#include "frontends/vectornav/binary_message.hpp"
#include "frontends/vectornav/field_io.hpp"

namespace navfuse::frontends::vectornav {

// Errata A8 (digest §10; ICD L873 vs L1172): FracSec is uint16 in the Time group and int16
// ("typically positive, but may be negative") in the GNSS groups.
enum class FracSecFormat : std::uint8_t { kUnsigned16, kSigned16 };

template <class Io>
void visit_utc(Io& io, UtcFields& u, FracSecFormat frac) {
  io.field("utc_year_since_2000", u.year_since_2000);
  io.field("utc_month", u.month);
  io.field("utc_day", u.day);
  io.field("utc_hour", u.hour);
  io.field("utc_minute", u.minute);
  io.field("utc_second", u.second);
  if (frac == FracSecFormat::kSigned16) {
    auto v = static_cast<std::int16_t>(u.frac_ms);
    io.field("utc_frac_ms", v);
    u.frac_ms = v;
  } else {
    auto v = static_cast<std::uint16_t>(u.frac_ms);
    io.field("utc_frac_ms", v);
    u.frac_ms = v;
  }
}

template <class Io>
void visit_time_type(unsigned bit, Io& io, TimeFields& f) {
  switch (bit) {
    case time_type::kTimeStartup: io.field("time_startup_ns", f.time_startup_ns); break;
    case time_type::kTimeGps: io.field("time_gps_ns", f.time_gps_ns); break;
    case time_type::kGpsTow: io.field("gps_tow_ns", f.gps_tow_ns); break;
    case time_type::kGpsWeek: io.field("gps_week", f.gps_week); break;
    case time_type::kTimeSyncIn: io.field("time_sync_in_ns", f.time_sync_in_ns); break;
    case time_type::kTimeGpsPps: io.field("time_gps_pps_ns", f.time_gps_pps_ns); break;
    case time_type::kTimeUtc: visit_utc(io, f.utc, FracSecFormat::kUnsigned16); break;
    case time_type::kSyncInCnt: io.field("sync_in_cnt", f.sync_in_cnt); break;
    case time_type::kSyncOutCnt: io.field("sync_out_cnt", f.sync_out_cnt); break;
    case time_type::kTimeStatus: io.field("time_status", f.time_status); break;
    default: break;  // unreachable: the header parser refuses unknown type bits
  }
}

}  // namespace navfuse::frontends::vectornav

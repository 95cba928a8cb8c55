#include "frontends/mip/time_fields.hpp"

#include "core/time/gps_time.hpp"
#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {

void write_gps_timestamp(std::int64_t gps_ns, bool valid, PacketWriter& w) {
  const time::WeekTow wt = time::week_tow_from_gps_ns(gps_ns);
  auto& f = w.field(shared::kGpsTimestamp);
  f.f64(wt.tow_s);
  f.u16(static_cast<std::uint16_t>(wt.week));
  f.u16(valid ? shared::kGpsTimeValid : 0);
}

void write_time_fields(const MeasurementHeader& h, PacketWriter& w) {
  if (h.time_source == TimeSource::kGps) {
    write_gps_timestamp(h.time_ns, true, w);
  } else {
    w.field(shared::kReferenceTimestamp).u64(static_cast<std::uint64_t>(h.time_ns < 0 ? 0 : h.time_ns));
  }
}

}  // namespace navfuse::frontends::mip

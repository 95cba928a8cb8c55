// NAVTIME: GPS, BDS, Galileo and GLONASS time (spec L1320-L1346; digest §4.7, §11 item 24).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {
namespace {
// The example and the parameter table (L1332-L1345) have 13 fields; the syntax line L1324 is
// garbled (GPST twice, GPSQ missing): erratum applied per digest §11 item 24.
constexpr std::size_t kNavtimeDataFields = 13;
}  // namespace

std::optional<Navtime> decode_navtime(const nmea::Fields& f) {
  if (f.data_count() != kNavtimeDataFields) return std::nullopt;
  Navtime m;
  if (!read(f[1], m.gps_week) || !read(f[2], m.gps_tow_s) || !read(f[3], m.gps_quality) ||
      !read(f[4], m.bds_week) || !read(f[5], m.bds_tow_s) || !read(f[6], m.bds_quality) ||
      !read(f[7], m.gal_week) || !read(f[8], m.gal_tow_s) || !read(f[9], m.gal_quality) ||
      !read(f[10], m.glo_four_year) || !read(f[11], m.glo_day) ||
      !read(f[12], m.glo_time_of_day_s) || !read(f[13], m.glo_quality)) {
    return std::nullopt;
  }
  return m;
}

bool encode(const Navtime& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin("NAVTIME");
  w.add_uint(m.gps_week);
  w.add(m.gps_tow_s);
  w.add_uint(m.gps_quality);
  w.add_uint(m.bds_week);
  w.add(m.bds_tow_s);
  w.add_uint(m.bds_quality);
  w.add_uint(m.gal_week);
  w.add(m.gal_tow_s);
  w.add_uint(m.gal_quality);
  w.add_uint(m.glo_four_year);
  w.add_uint(m.glo_day);
  w.add(m.glo_time_of_day_s);
  w.add_uint(m.glo_quality);
  return w.finish(out);
}

void append_fields(const Navtime& m, frontends::FrameRecord& r) {
  using nmea::put;
  put(r, "gps_week", m.gps_week);
  put(r, "gps_tow_s", m.gps_tow_s);
  put(r, "gps_quality", m.gps_quality);
  put(r, "bds_week", m.bds_week);
  put(r, "bds_tow_s", m.bds_tow_s);
  put(r, "bds_quality", m.bds_quality);
  put(r, "gal_week", m.gal_week);
  put(r, "gal_tow_s", m.gal_tow_s);
  put(r, "gal_quality", m.gal_quality);
  put(r, "glo_four_year_interval", m.glo_four_year);
  put(r, "glo_day", m.glo_day);
  put(r, "glo_time_of_day_s", m.glo_time_of_day_s);
  put(r, "glo_quality", m.glo_quality);
}

}  // namespace navfuse::frontends::unicore

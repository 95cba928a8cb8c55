// NAVPOS: GNSS position, ECEF and geodetic (spec L1277-L1298; digest §4.5).
#include <cmath>

#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {
namespace {
constexpr std::size_t kNavposDataFields = 9;  // syntax L1281
}  // namespace

std::optional<Navpos> decode_navpos(const nmea::Fields& f) {
  if (f.data_count() != kNavposDataFields) return std::nullopt;
  Navpos m;
  if (!read(f[1], m.time_ms) || !read(f[2], m.system) || !read(f[3], m.quality) ||
      !read(f[4], m.ecef_m[0]) || !read(f[5], m.ecef_m[1]) || !read(f[6], m.ecef_m[2]) ||
      !read(f[7], m.lat_deg) || !read(f[8], m.lon_deg) || !read(f[9], m.height_m)) {
    return std::nullopt;
  }
  if (std::abs(m.lat_deg.value) > 90.0 || std::abs(m.lon_deg.value) > 180.0) return std::nullopt;
  return m;
}

bool encode(const Navpos& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin("NAVPOS");
  w.add_uint(m.time_ms);
  w.add_uint(m.system);
  w.add_uint(m.quality);
  for (const auto& c : m.ecef_m) w.add(c);
  w.add(m.lat_deg);
  w.add(m.lon_deg);
  w.add(m.height_m);
  return w.finish(out);
}

void append_fields(const Navpos& m, frontends::FrameRecord& r) {
  using nmea::put;
  put(r, "time_of_week_ms", m.time_ms);
  put(r, "system_mask", m.system);
  put(r, "quality", m.quality);
  put(r, "ecef_x_m", m.ecef_m[0]);
  put(r, "ecef_y_m", m.ecef_m[1]);
  put(r, "ecef_z_m", m.ecef_m[2]);
  put(r, "lat_deg", m.lat_deg);
  put(r, "lon_deg", m.lon_deg);
  put(r, "height_m", m.height_m);
}

}  // namespace navfuse::frontends::unicore

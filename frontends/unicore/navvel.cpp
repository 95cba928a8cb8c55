// NAVVEL: GNSS velocity in ECEF (spec L1300-L1318; digest §4.6).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {
namespace {
constexpr std::size_t kNavvelDataFields = 7;  // syntax L1304
}  // namespace

std::optional<Navvel> decode_navvel(const nmea::Fields& f) {
  if (f.data_count() != kNavvelDataFields) return std::nullopt;
  Navvel m;
  if (!read(f[1], m.time_ms) || !read(f[2], m.system) || !read(f[3], m.quality) ||
      !read(f[4], m.vel_ecef_mps[0]) || !read(f[5], m.vel_ecef_mps[1]) ||
      !read(f[6], m.vel_ecef_mps[2]) || !read(f[7], m.clock_drift_mps)) {
    return std::nullopt;
  }
  return m;
}

bool encode(const Navvel& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin("NAVVEL");
  w.add_uint(m.time_ms);
  w.add_uint(m.system);
  w.add_uint(m.quality);
  for (const auto& v : m.vel_ecef_mps) w.add(v);
  w.add(m.clock_drift_mps);
  return w.finish(out);
}

void append_fields(const Navvel& m, frontends::FrameRecord& r) {
  using nmea::put;
  put(r, "time_of_week_ms", m.time_ms);
  put(r, "system_mask", m.system);
  put(r, "quality", m.quality);
  put(r, "vel_ecef_x_mps", m.vel_ecef_mps[0]);
  put(r, "vel_ecef_y_mps", m.vel_ecef_mps[1]);
  put(r, "vel_ecef_z_mps", m.vel_ecef_mps[2]);
  put(r, "clock_drift_mps", m.clock_drift_mps);
}

}  // namespace navfuse::frontends::unicore

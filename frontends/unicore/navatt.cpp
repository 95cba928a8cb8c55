// NAVATT: attitude and its standard deviations (spec L1366-L1388; digest §4.9).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {
namespace {
constexpr std::size_t kNavattDataFields = 8;  // syntax L1370
}  // namespace

std::optional<Navatt> decode_navatt(const nmea::Fields& f) {
  if (f.data_count() != kNavattDataFields) return std::nullopt;
  Navatt m;
  if (!nmea::read_optional(f[1], m.time) || !read(f[2], m.quality) || !read(f[3], m.roll_e5deg) ||
      !read(f[4], m.pitch_e5deg) || !read(f[5], m.yaw_e5deg) || !read(f[6], m.roll_std_e5deg) ||
      !read(f[7], m.pitch_std_e5deg) || !read(f[8], m.yaw_std_e5deg)) {
    return std::nullopt;
  }
  return m;
}

bool encode(const Navatt& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin("NAVATT");
  nmea::add_optional(w, m.time);
  w.add_uint(m.quality);
  w.add_int(m.roll_e5deg);
  w.add_int(m.pitch_e5deg);
  w.add_int(m.yaw_e5deg);
  w.add_uint(m.roll_std_e5deg);
  w.add_uint(m.pitch_std_e5deg);
  w.add_uint(m.yaw_std_e5deg);
  return w.finish(out);
}

void append_fields(const Navatt& m, frontends::FrameRecord& r) {
  using nmea::put;
  nmea::put_time(r, m.time);
  put(r, "quality", m.quality);
  put(r, "roll_deg", m.roll_e5deg * kNavattDegPerUnit);
  put(r, "pitch_deg", m.pitch_e5deg * kNavattDegPerUnit);
  put(r, "yaw_deg", m.yaw_e5deg * kNavattDegPerUnit);
  put(r, "roll_std_deg", m.roll_std_e5deg * kNavattDegPerUnit);
  put(r, "pitch_std_deg", m.pitch_std_e5deg * kNavattDegPerUnit);
  put(r, "yaw_std_deg", m.yaw_std_e5deg * kNavattDegPerUnit);
}

}  // namespace navfuse::frontends::unicore

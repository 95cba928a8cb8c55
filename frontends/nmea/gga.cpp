// GGA: time, position, fix quality (spec h51 L863-L893, h30 L1085-L1116).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
constexpr std::size_t kGgaDataFields = 14;  // syntax line L866
constexpr std::string_view kUnitMetres = "M";
}  // namespace

std::optional<Gga> decode_gga(const Fields& f) {
  if (f.data_count() != kGgaDataFields) return std::nullopt;
  const auto name = split_sentence_name(f.name());
  if (!name) return std::nullopt;
  Gga s;
  s.talker = name->talker;
  const std::optional<std::uint32_t> quality = parse_uint(f[6]);
  if (!quality) return std::nullopt;
  s.quality = *quality;
  s.height_unit = !f[10].empty();
  if (!read_optional(f[1], s.time) || !read_optional_lat(f, 2, s.lat) ||
      !read_optional_lon(f, 4, s.lon) || !read_optional(f[7], s.num_sats) ||
      !read_optional(f[8], s.hdop) || !read_optional(f[9], s.height_m) ||
      !read_optional(f[11], s.geoid_separation_m) || !read_optional(f[13], s.diff_age_s) ||
      !read_optional(f[14], s.diff_station)) {
    return std::nullopt;
  }
  return s;
}

bool encode(const Gga& s, std::vector<std::uint8_t>& out) {
  SentenceWriter w;
  begin_sentence(w, s.talker, "GGA");
  add_optional(w, s.time);
  add_optional_lat(w, s.lat);
  add_optional_lon(w, s.lon);
  w.add_uint(s.quality);
  add_optional(w, s.num_sats);
  add_optional(w, s.hdop);
  add_optional(w, s.height_m);
  w.add(s.height_unit ? kUnitMetres : std::string_view{});
  add_optional(w, s.geoid_separation_m);
  w.add(kUnitMetres);
  add_optional(w, s.diff_age_s);
  add_optional(w, s.diff_station);
  return w.finish(out);
}

void append_fields(const Gga& s, frontends::FrameRecord& r) {
  put_time(r, s.time);
  put_latlon(r, s.lat, s.lon);
  put(r, "quality", s.quality);
  put(r, "num_sats", s.num_sats);
  put(r, "hdop", s.hdop);
  put(r, "height_field_m", s.height_m);
  put(r, "geoid_separation_m", s.geoid_separation_m);
  put(r, "diff_age_s", s.diff_age_s);
  put(r, "diff_station", s.diff_station);
}

}  // namespace navfuse::frontends::nmea

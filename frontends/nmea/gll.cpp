// GLL: position and time (spec h51 L895-L917, h30 L1118-L1141).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
constexpr std::size_t kGllDataFields = 7;  // syntax line L898
}  // namespace

std::optional<Gll> decode_gll(const Fields& f) {
  if (f.data_count() != kGllDataFields) return std::nullopt;
  const auto name = split_sentence_name(f.name());
  const std::optional<char> status = parse_char(f[6]);
  if (!name || !status) return std::nullopt;
  Gll s;
  s.talker = name->talker;
  s.status = *status;
  if (!read_optional_lat(f, 1, s.lat) || !read_optional_lon(f, 3, s.lon) ||
      !read_optional(f[5], s.time) || !read_optional(f[7], s.mode)) {
    return std::nullopt;
  }
  return s;
}

bool encode(const Gll& s, std::vector<std::uint8_t>& out) {
  SentenceWriter w;
  begin_sentence(w, s.talker, "GLL");
  add_optional_lat(w, s.lat);
  add_optional_lon(w, s.lon);
  add_optional(w, s.time);
  w.add(s.status);
  add_optional(w, s.mode);
  return w.finish(out);
}

void append_fields(const Gll& s, frontends::FrameRecord& r) {
  put_latlon(r, s.lat, s.lon);
  put_time(r, s.time);
  put(r, "status", s.status);
  put(r, "mode", s.mode);
}

}  // namespace navfuse::frontends::nmea

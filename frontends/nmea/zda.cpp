// ZDA: UTC date and time (spec h51 L1034-L1057, h30 L1254-L1273).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
constexpr std::size_t kZdaDataFields = 6;  // L1037
}  // namespace

std::optional<Zda> decode_zda(const Fields& f) {
  if (f.data_count() != kZdaDataFields) return std::nullopt;
  const auto name = split_sentence_name(f.name());
  if (!name) return std::nullopt;
  Zda s;
  s.talker = name->talker;
  if (!read_optional(f[1], s.time) || !read_optional(f[2], s.day) ||
      !read_optional(f[3], s.month) || !read_optional(f[4], s.year) ||
      !read_optional(f[5], s.zone_hours) || !read_optional(f[6], s.zone_minutes)) {
    return std::nullopt;
  }
  return s;
}

bool encode(const Zda& s, std::vector<std::uint8_t>& out) {
  SentenceWriter w;
  begin_sentence(w, s.talker, "ZDA");
  add_optional(w, s.time);
  add_optional(w, s.day);
  add_optional(w, s.month);
  add_optional(w, s.year);
  add_optional(w, s.zone_hours);
  add_optional(w, s.zone_minutes);
  return w.finish(out);
}

void append_fields(const Zda& s, frontends::FrameRecord& r) {
  put_time(r, s.time);
  put(r, "utc_day", s.day);
  put(r, "utc_month", s.month);
  put(r, "utc_year", s.year);
  put(r, "zone_hours", s.zone_hours);
  put(r, "zone_minutes", s.zone_minutes);
}

}  // namespace navfuse::frontends::nmea

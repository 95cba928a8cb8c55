// RMC: recommended minimum data (spec h51 L977-L1007, h30 L1197-L1226).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
constexpr std::size_t kRmcH30DataFields = 12;  // L1200
constexpr std::size_t kRmcH51DataFields = 13;  // L980: adds navStatus
}  // namespace

std::optional<Rmc> decode_rmc(const Fields& f) {
  const std::size_t n = f.data_count();
  if (n != kRmcH30DataFields && n != kRmcH51DataFields) return std::nullopt;
  const auto name = split_sentence_name(f.name());
  const std::optional<char> status = parse_char(f[2]);
  if (!name || !status) return std::nullopt;
  Rmc s;
  s.talker = name->talker;
  s.dialect = n == kRmcH51DataFields ? Dialect::kH51 : Dialect::kH30;
  s.status = *status;
  if (!f[9].empty()) {
    s.date = parse_date_ddmmyy(f[9]);
    if (!s.date) return std::nullopt;
  }
  if (!read_optional(f[1], s.time) || !read_optional_lat(f, 3, s.lat) ||
      !read_optional_lon(f, 5, s.lon) || !read_optional(f[7], s.speed_knots) ||
      !read_optional(f[8], s.course_deg) || !read_optional(f[10], s.magnetic_variation_deg) ||
      !read_optional(f[11], s.variation_direction) || !read_optional(f[12], s.mode)) {
    return std::nullopt;
  }
  if (s.dialect == Dialect::kH51 && !read_optional(f[13], s.nav_status)) return std::nullopt;
  return s;
}

bool encode(const Rmc& s, std::vector<std::uint8_t>& out) {
  SentenceWriter w;
  begin_sentence(w, s.talker, "RMC");
  add_optional(w, s.time);
  w.add(s.status);
  add_optional_lat(w, s.lat);
  add_optional_lon(w, s.lon);
  add_optional(w, s.speed_knots);
  add_optional(w, s.course_deg);
  if (s.date) add_date_ddmmyy(w, *s.date); else w.add_empty();
  add_optional(w, s.magnetic_variation_deg);
  add_optional(w, s.variation_direction);
  add_optional(w, s.mode);
  if (s.dialect == Dialect::kH51) add_optional(w, s.nav_status);
  return w.finish(out);
}

void append_fields(const Rmc& s, frontends::FrameRecord& r) {
  put_time(r, s.time);
  put(r, "status", s.status);
  put_latlon(r, s.lat, s.lon);
  if (s.speed_knots) {
    put(r, "speed_mps", s.speed_knots->value * kMetresPerSecondPerKnot);
  } else {
    put_null(r, "speed_mps");
  }
  put(r, "course_deg", s.course_deg);
  if (s.date) {
    put(r, "utc_year", static_cast<std::int64_t>(s.date->year));
    put(r, "utc_month", static_cast<std::int64_t>(s.date->month));
    put(r, "utc_day", static_cast<std::int64_t>(s.date->day));
  } else {
    put_null(r, "utc_year");
    put_null(r, "utc_month");
    put_null(r, "utc_day");
  }
  put(r, "magnetic_variation_deg", s.magnetic_variation_deg);
  put(r, "variation_direction", s.variation_direction);
  put(r, "mode", s.mode);
  put(r, "nav_status", s.nav_status);
}

}  // namespace navfuse::frontends::nmea

// Field readers/writers shared by the NMEA sentence files (gga.cpp, rmc.cpp, ...).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }
constexpr double kNsToS = 1e-9;
}  // namespace

std::optional<SentenceName> split_sentence_name(std::string_view name) {
  if (name.size() != kTalkerChars + kSentenceTypeChars) return std::nullopt;
  SentenceName n;
  n.talker = {upper(name[0]), upper(name[1])};
  for (std::size_t i = 0; i < kSentenceTypeChars; ++i) n.type[i] = upper(name[kTalkerChars + i]);
  return n;
}

void begin_sentence(SentenceWriter& w, Talker talker, std::string_view type) {
  w.begin(std::string_view(talker.data(), talker.size()));
  w.append(type);
}

void add_optional(SentenceWriter& w, const std::optional<Real>& v) {
  if (v) w.add(*v); else w.add_empty();
}
void add_optional(SentenceWriter& w, const std::optional<Count>& v) {
  if (v) w.add(*v); else w.add_empty();
}
void add_optional(SentenceWriter& w, const std::optional<char>& v) {
  if (v) w.add(*v); else w.add_empty();
}
void add_optional(SentenceWriter& w, const std::optional<TimeOfDay>& v) {
  if (v) add_time_of_day(w, *v); else w.add_empty();
}
void add_optional_lat(SentenceWriter& w, const std::optional<LatLonField>& v) {
  if (v) {
    add_latitude(w, *v);
  } else {
    w.add_empty();
    w.add_empty();
  }
}
void add_optional_lon(SentenceWriter& w, const std::optional<LatLonField>& v) {
  if (v) {
    add_longitude(w, *v);
  } else {
    w.add_empty();
    w.add_empty();
  }
}

bool read_optional(std::string_view field, std::optional<Real>& v) {
  v.reset();
  if (field.empty()) return true;
  v = parse_real(field);
  return v.has_value();
}
bool read_optional(std::string_view field, std::optional<Count>& v) {
  v.reset();
  if (field.empty()) return true;
  v = parse_count(field);
  return v.has_value();
}
bool read_optional(std::string_view field, std::optional<char>& v) {
  v.reset();
  if (field.empty()) return true;
  v = parse_char(field);
  return v.has_value();
}
bool read_optional(std::string_view field, std::optional<TimeOfDay>& v) {
  v.reset();
  if (field.empty()) return true;
  v = parse_time_of_day(field);
  return v.has_value();
}
bool read_optional_lat(const Fields& f, std::size_t i, std::optional<LatLonField>& v) {
  v.reset();
  if (f[i].empty() && f[i + 1].empty()) return true;
  v = parse_latitude(f[i], f[i + 1]);
  return v.has_value();
}
bool read_optional_lon(const Fields& f, std::size_t i, std::optional<LatLonField>& v) {
  v.reset();
  if (f[i].empty() && f[i + 1].empty()) return true;
  v = parse_longitude(f[i], f[i + 1]);
  return v.has_value();
}

void put_time(frontends::FrameRecord& r, const std::optional<TimeOfDay>& t) {
  if (t) {
    put(r, "utc_time_of_day_s", static_cast<double>(t->ns) * kNsToS);
  } else {
    put_null(r, "utc_time_of_day_s");
  }
}

void put_latlon(frontends::FrameRecord& r, const std::optional<LatLonField>& lat,
                const std::optional<LatLonField>& lon) {
  if (lat) put(r, "lat_deg", lat->deg); else put_null(r, "lat_deg");
  if (lon) put(r, "lon_deg", lon->deg); else put_null(r, "lon_deg");
}

}  // namespace navfuse::frontends::nmea

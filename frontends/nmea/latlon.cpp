#include "frontends/nmea/latlon.hpp"

#include <cmath>

#include "frontends/nmea/fields.hpp"

namespace navfuse::frontends::nmea {
namespace {

constexpr double kMinutesPerDegree = 60.0;
constexpr int kLatDegreeDigits = 2;  // "ddmm.mmmm"
constexpr int kLonDegreeDigits = 3;  // "dddmm.mmmm"

std::optional<LatLonField> parse_angle(std::string_view value, std::string_view hemisphere,
                                       char positive, char negative, double max_deg) {
  const std::optional<Real> r = parse_real(value);
  const std::optional<char> h = parse_char(hemisphere);
  if (!r || !h || r->value < 0.0) return std::nullopt;
  const char hemi = static_cast<char>(*h >= 'a' && *h <= 'z' ? *h - 'a' + 'A' : *h);
  if (hemi != positive && hemi != negative) return std::nullopt;
  const double whole_deg = std::floor(r->value / 100.0);
  const double minutes = r->value - whole_deg * 100.0;
  if (minutes >= kMinutesPerDegree) return std::nullopt;
  const double deg = whole_deg + minutes / kMinutesPerDegree;
  if (deg > max_deg) return std::nullopt;
  return LatLonField{hemi == positive ? deg : -deg, r->decimals};
}

void add_angle(SentenceWriter& w, const LatLonField& f, int degree_digits, char positive,
               char negative) {
  const double mag = std::fabs(f.deg);
  double whole = std::floor(mag);
  // Round the minutes to the printed decimals first: they can reach 60 (carry into the degrees)
  // or 10 (no zero padding needed any more).
  const double scale = std::pow(10.0, f.minute_decimals);
  double minutes = std::round((mag - whole) * kMinutesPerDegree * scale) / scale;
  if (minutes >= kMinutesPerDegree) {
    whole += 1.0;
    minutes = 0.0;
  }
  w.add_uint(static_cast<std::uint64_t>(whole), degree_digits);
  if (minutes < 10.0) w.append("0");
  w.append_fixed(minutes, f.minute_decimals);
  w.add(f.deg < 0.0 ? negative : positive);
}

}  // namespace

std::optional<LatLonField> parse_latitude(std::string_view value, std::string_view hemisphere) {
  return parse_angle(value, hemisphere, 'N', 'S', 90.0);
}

std::optional<LatLonField> parse_longitude(std::string_view value, std::string_view hemisphere) {
  return parse_angle(value, hemisphere, 'E', 'W', 180.0);
}

void add_latitude(SentenceWriter& w, const LatLonField& lat) {
  add_angle(w, lat, kLatDegreeDigits, 'N', 'S');
}

void add_longitude(SentenceWriter& w, const LatLonField& lon) {
  add_angle(w, lon, kLonDegreeDigits, 'E', 'W');
}

}  // namespace navfuse::frontends::nmea

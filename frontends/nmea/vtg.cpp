// VTG: course and speed over ground (spec h51 L1009-L1032, h30 L1228-L1252).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
constexpr std::size_t kVtgDataFields = 9;  // L1012
}  // namespace

std::optional<Vtg> decode_vtg(const Fields& f) {
  if (f.data_count() != kVtgDataFields) return std::nullopt;
  const auto name = split_sentence_name(f.name());
  // The unit letters are constants (T, M, N, K); anything else is not a VTG we understand.
  if (!name || !iequals(f[2], "T") || !iequals(f[4], "M") || !iequals(f[6], "N") ||
      !iequals(f[8], "K")) {
    return std::nullopt;
  }
  Vtg s;
  s.talker = name->talker;
  if (!read_optional(f[1], s.course_true_deg) || !read_optional(f[3], s.course_magnetic_deg) ||
      !read_optional(f[5], s.speed_knots) || !read_optional(f[7], s.speed_kph) ||
      !read_optional(f[9], s.mode)) {
    return std::nullopt;
  }
  return s;
}

bool encode(const Vtg& s, std::vector<std::uint8_t>& out) {
  SentenceWriter w;
  begin_sentence(w, s.talker, "VTG");
  add_optional(w, s.course_true_deg);
  w.add('T');
  add_optional(w, s.course_magnetic_deg);
  w.add('M');
  add_optional(w, s.speed_knots);
  w.add('N');
  add_optional(w, s.speed_kph);
  w.add('K');
  add_optional(w, s.mode);
  return w.finish(out);
}

void append_fields(const Vtg& s, frontends::FrameRecord& r) {
  put(r, "course_true_deg", s.course_true_deg);
  put(r, "course_magnetic_deg", s.course_magnetic_deg);
  if (s.speed_knots) {
    put(r, "speed_knots_mps", s.speed_knots->value * kMetresPerSecondPerKnot);
  } else {
    put_null(r, "speed_knots_mps");
  }
  if (s.speed_kph) {
    put(r, "speed_kph_mps", s.speed_kph->value * kMetresPerSecondPerKph);
  } else {
    put_null(r, "speed_kph_mps");
  }
  put(r, "mode", s.mode);
}

}  // namespace navfuse::frontends::nmea

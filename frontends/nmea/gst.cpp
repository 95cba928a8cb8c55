// GST: pseudorange error statistics (spec h51 L1059-L1081; no h30 form).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
constexpr std::size_t kGstDataFields = 8;  // L1062, digest §10.1 fixed example
}  // namespace

std::optional<Gst> decode_gst(const Fields& f) {
  if (f.data_count() != kGstDataFields) return std::nullopt;
  const auto name = split_sentence_name(f.name());
  if (!name) return std::nullopt;
  Gst s;
  s.talker = name->talker;
  if (!read_optional(f[1], s.time) || !read_optional(f[2], s.range_rms_m) ||
      !read_optional(f[3], s.std_major_m) || !read_optional(f[4], s.std_minor_m) ||
      !read_optional(f[5], s.orientation_deg) || !read_optional(f[6], s.std_lat_m) ||
      !read_optional(f[7], s.std_lon_m) || !read_optional(f[8], s.std_alt_m)) {
    return std::nullopt;
  }
  return s;
}

bool encode(const Gst& s, std::vector<std::uint8_t>& out) {
  SentenceWriter w;
  begin_sentence(w, s.talker, "GST");
  add_optional(w, s.time);
  add_optional(w, s.range_rms_m);
  add_optional(w, s.std_major_m);
  add_optional(w, s.std_minor_m);
  add_optional(w, s.orientation_deg);
  add_optional(w, s.std_lat_m);
  add_optional(w, s.std_lon_m);
  add_optional(w, s.std_alt_m);
  return w.finish(out);
}

void append_fields(const Gst& s, frontends::FrameRecord& r) {
  put_time(r, s.time);
  put(r, "range_rms_m", s.range_rms_m);
  put(r, "std_major_m", s.std_major_m);
  put(r, "std_minor_m", s.std_minor_m);
  put(r, "orientation_deg", s.orientation_deg);
  put(r, "std_lat_m", s.std_lat_m);
  put(r, "std_lon_m", s.std_lon_m);
  put(r, "std_alt_m", s.std_alt_m);
}

}  // namespace navfuse::frontends::nmea

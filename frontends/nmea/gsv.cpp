// GSV: satellites in view (spec h51 L948-L975, h30 L1168-L1195).
#include <string>

#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
constexpr std::size_t kGsvHeaderFields = 3;  // NoMsg, MsgNo, NoSv
constexpr std::size_t kGsvFieldsPerSat = 4;  // sv, elv, az, cn0
}  // namespace

std::optional<Gsv> decode_gsv(const Fields& f) {
  const std::size_t n = f.data_count();
  if (n < kGsvHeaderFields) return std::nullopt;
  // The last sentence of a group is short (1-4 satellite blocks, digest §4.4.4); h51 appends one
  // signalID field (L968), so the remainder tells the dialects apart.
  const std::size_t rest = n - kGsvHeaderFields;
  const bool h51 = rest % kGsvFieldsPerSat == 1;
  if (!h51 && rest % kGsvFieldsPerSat != 0) return std::nullopt;
  const std::size_t sats = rest / kGsvFieldsPerSat;
  if (sats > kGsvSatsPerSentence) return std::nullopt;
  const auto name = split_sentence_name(f.name());
  const auto total = parse_count(f[1]);
  const auto number = parse_count(f[2]);
  const auto in_view = parse_count(f[3]);
  if (!name || !total || !number || !in_view) return std::nullopt;
  Gsv s;
  s.talker = name->talker;
  s.dialect = h51 ? Dialect::kH51 : Dialect::kH30;
  s.total_sentences = *total;
  s.sentence_number = *number;
  s.sats_in_view = *in_view;
  s.sat_count = sats;
  for (std::size_t i = 0; i < sats; ++i) {
    const std::size_t k = 1 + kGsvHeaderFields + i * kGsvFieldsPerSat;
    const auto sv = parse_count(f[k]);
    if (!sv) return std::nullopt;
    s.sats[i].number = *sv;
    if (!read_optional(f[k + 1], s.sats[i].elevation_deg) ||
        !read_optional(f[k + 2], s.sats[i].azimuth_deg) ||
        !read_optional(f[k + 3], s.sats[i].cn0_dbhz)) {
      return std::nullopt;
    }
  }
  if (h51 && !read_optional(f[n], s.signal_id)) return std::nullopt;
  return s;
}

bool encode(const Gsv& s, std::vector<std::uint8_t>& out) {
  if (s.sat_count > kGsvSatsPerSentence) return false;
  SentenceWriter w;
  begin_sentence(w, s.talker, "GSV");
  w.add(s.total_sentences);
  w.add(s.sentence_number);
  w.add(s.sats_in_view);
  for (std::size_t i = 0; i < s.sat_count; ++i) {
    w.add(s.sats[i].number);
    add_optional(w, s.sats[i].elevation_deg);
    add_optional(w, s.sats[i].azimuth_deg);
    add_optional(w, s.sats[i].cn0_dbhz);
  }
  if (s.dialect == Dialect::kH51) add_optional(w, s.signal_id);
  return w.finish(out);
}

void append_fields(const Gsv& s, frontends::FrameRecord& r) {
  put(r, "total_sentences", s.total_sentences);
  put(r, "sentence_number", s.sentence_number);
  put(r, "sats_in_view", s.sats_in_view);
  for (std::size_t i = 0; i < s.sat_count; ++i) {
    const std::string prefix = "sat" + std::to_string(i + 1);
    const SatId id = sat_from_nmea(s.sats[i].number.value, s.talker, s.dialect);
    put(r, prefix + "_number", s.sats[i].number);
    put(r, prefix + "_system", to_string(id.system));
    put(r, prefix + "_prn", static_cast<std::uint32_t>(id.prn));
    put(r, prefix + "_elevation_deg", s.sats[i].elevation_deg);
    put(r, prefix + "_azimuth_deg", s.sats[i].azimuth_deg);
    put(r, prefix + "_cn0_dbhz", s.sats[i].cn0_dbhz);
  }
  put(r, "signal_id", s.signal_id);
}

}  // namespace navfuse::frontends::nmea

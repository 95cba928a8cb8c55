// GSA: DOPs and satellites used (spec h51 L919-L946, h30 L1143-L1166).
#include <string>

#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
// h30: Smode, FS, 12 satellites, PDOP, HDOP, VDOP (L1146); h51 adds systemID (L922).
constexpr std::size_t kGsaH30DataFields = 2 + kGsaSatSlots + 3;
constexpr std::size_t kGsaH51DataFields = kGsaH30DataFields + 1;
constexpr std::size_t kFirstSatField = 3;
}  // namespace

std::optional<Gsa> decode_gsa(const Fields& f) {
  const std::size_t n = f.data_count();
  if (n != kGsaH30DataFields && n != kGsaH51DataFields) return std::nullopt;
  const auto name = split_sentence_name(f.name());
  const std::optional<char> mode = parse_char(f[1]);
  const std::optional<std::uint32_t> fix = parse_uint(f[2]);
  if (!name || !mode || !fix) return std::nullopt;
  Gsa s;
  s.talker = name->talker;
  s.dialect = n == kGsaH51DataFields ? Dialect::kH51 : Dialect::kH30;
  s.selection_mode = *mode;
  s.fix = *fix;
  for (std::size_t i = 0; i < kGsaSatSlots; ++i) {
    if (!read_optional(f[kFirstSatField + i], s.sats[i])) return std::nullopt;
  }
  const std::size_t dop = kFirstSatField + kGsaSatSlots;
  if (!read_optional(f[dop], s.pdop) || !read_optional(f[dop + 1], s.hdop) ||
      !read_optional(f[dop + 2], s.vdop)) {
    return std::nullopt;
  }
  if (s.dialect == Dialect::kH51 && !read_optional(f[dop + 3], s.system_id)) return std::nullopt;
  return s;
}

bool encode(const Gsa& s, std::vector<std::uint8_t>& out) {
  SentenceWriter w;
  begin_sentence(w, s.talker, "GSA");
  w.add(s.selection_mode);
  w.add_uint(s.fix);
  for (const auto& sat : s.sats) add_optional(w, sat);
  add_optional(w, s.pdop);
  add_optional(w, s.hdop);
  add_optional(w, s.vdop);
  if (s.dialect == Dialect::kH51) add_optional(w, s.system_id);
  return w.finish(out);
}

void append_fields(const Gsa& s, frontends::FrameRecord& r) {
  put(r, "selection_mode", s.selection_mode);
  put(r, "fix", s.fix);
  // The talker alone cannot resolve h51 numbers under GN: the systemID names the constellation.
  Talker talker = s.talker;
  if (s.system_id) {
    constexpr Talker kBySystemId[] = {{'G', 'N'}, {'G', 'P'}, {'G', 'L'}, {'G', 'A'}, {'G', 'B'}};
    if (s.system_id->value < std::size(kBySystemId)) talker = kBySystemId[s.system_id->value];
  }
  for (std::size_t i = 0; i < kGsaSatSlots; ++i) {
    const std::string prefix = "sat" + std::to_string(i + 1);
    put(r, prefix + "_number", s.sats[i]);
    if (s.sats[i]) {
      const SatId id = sat_from_nmea(s.sats[i]->value, talker, s.dialect);
      put(r, prefix + "_system", to_string(id.system));
      put(r, prefix + "_prn", static_cast<std::uint32_t>(id.prn));
    } else {
      put_null(r, prefix + "_system");
      put_null(r, prefix + "_prn");
    }
  }
  put(r, "pdop", s.pdop);
  put(r, "hdop", s.hdop);
  put(r, "vdop", s.vdop);
  put(r, "system_id", s.system_id);
}

}  // namespace navfuse::frontends::nmea

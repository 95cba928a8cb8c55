// HDT: true heading (NMEA 0183 "HDT - Heading - True": heading in degrees, then the letter T).
// The UM220 does not write it; navfuse's NMEA output does (GNSS compass / INS heading).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {
constexpr std::size_t kHdtDataFields = 2;  // heading, "T"
}  // namespace

std::optional<Hdt> decode_hdt(const Fields& f) {
  if (f.data_count() != kHdtDataFields || f[2] != "T") return std::nullopt;
  const auto name = split_sentence_name(f.name());
  if (!name) return std::nullopt;
  Hdt s;
  s.talker = name->talker;
  if (!read_optional(f[1], s.heading_deg)) return std::nullopt;
  return s;
}

bool encode(const Hdt& s, std::vector<std::uint8_t>& out) {
  SentenceWriter w;
  begin_sentence(w, s.talker, "HDT");
  add_optional(w, s.heading_deg);
  w.add('T');
  return w.finish(out);
}

}  // namespace navfuse::frontends::nmea

// SNRSTAT: INS initialisation, odometer, installation and map-matching state (spec L805-L821).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {
namespace {
constexpr std::size_t kSnrstatFieldsBeforeR26 = 3;  // mapstat added in R2.6 (L31)
constexpr std::size_t kSnrstatFields = 4;           // syntax L808
}  // namespace

std::optional<Snrstat> decode_snrstat(const nmea::Fields& f) {
  const std::size_t n = f.data_count();
  if (n != kSnrstatFields && n != kSnrstatFieldsBeforeR26) return std::nullopt;
  Snrstat m;
  if (!read(f[1], m.ins_status) || !read(f[2], m.odo_status) || !read(f[3], m.install_state)) {
    return std::nullopt;
  }
  if (n == kSnrstatFields) {
    std::int32_t map = 0;
    if (!read(f[4], map)) return std::nullopt;
    m.map_status = map;
  }
  return m;
}

bool encode(const Snrstat& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin("SNRSTAT");
  w.add_int(m.ins_status);
  w.add_int(m.odo_status);
  w.add_int(m.install_state);
  if (m.map_status) w.add_int(*m.map_status);
  return w.finish(out);
}

void append_fields(const Snrstat& m, frontends::FrameRecord& r) {
  nmea::put(r, "ins_status", m.ins_status);
  nmea::put(r, "odo_status", m.odo_status);
  nmea::put(r, "install_state", m.install_state);
  nmea::put(r, "map_status", m.map_status);
}

}  // namespace navfuse::frontends::unicore

// NOTICE: vendor maintenance output, on by default at 1 Hz, fields undocumented (spec L1453-L1457;
// digest §4.12): kept as text so that it is framed and reported, never interpreted.
#include <string>

#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {

std::optional<Notice> decode_notice(const nmea::Fields& f) {
  if (f.data_count() > kMaxNoticeFields) return std::nullopt;
  Notice m;
  m.count = f.data_count();
  for (std::size_t i = 0; i < m.count; ++i) m.fields[i] = f[i + 1];
  return m;
}

bool encode(const Notice& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin("NOTICE");
  for (std::size_t i = 0; i < m.count && i < kMaxNoticeFields; ++i) w.add(m.fields[i]);
  return w.finish(out);
}

void append_fields(const Notice& m, frontends::FrameRecord& r) {
  for (std::size_t i = 0; i < m.count; ++i) nmea::put(r, "field" + std::to_string(i + 1), m.fields[i]);
}

}  // namespace navfuse::frontends::unicore

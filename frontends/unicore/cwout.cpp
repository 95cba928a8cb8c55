// CWOUT: interference detection (spec L1440-L1451).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {
namespace {
constexpr std::size_t kCwoutDataFields = 2;  // syntax L1444
}  // namespace

std::optional<Cwout> decode_cwout(const nmea::Fields& f) {
  if (f.data_count() != kCwoutDataFields) return std::nullopt;
  Cwout m;
  if (!read(f[1], m.flag) || !read(f[2], m.ratio)) return std::nullopt;
  return m;
}

bool encode(const Cwout& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin("CWOUT");
  w.add_uint(m.flag);
  w.add_uint(m.ratio);
  return w.finish(out);
}

void append_fields(const Cwout& m, frontends::FrameRecord& r) {
  nmea::put(r, "interference_flag", m.flag);
  nmea::put(r, "interference_ratio", m.ratio);
}

}  // namespace navfuse::frontends::unicore

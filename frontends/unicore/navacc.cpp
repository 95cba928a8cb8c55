// NAVACC: horizontal position / velocity / course accuracy (spec L1348-L1364; digest §4.8).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {
namespace {
constexpr std::size_t kNavaccDataFields = 5;  // syntax L1352
constexpr double kMilli = 1e-3;
}  // namespace

std::optional<Navacc> decode_navacc(const nmea::Fields& f) {
  if (f.data_count() != kNavaccDataFields) return std::nullopt;
  // status is typed UINT but holds 'V'/'A' (L1359, digest §11 item 25): read it as a character.
  const std::optional<char> status = nmea::parse_char(f[2]);
  if (!status) return std::nullopt;
  Navacc m;
  m.status = *status;
  if (!nmea::read_optional(f[1], m.time) || !read(f[3], m.pos_acc_mm) ||
      !read(f[4], m.vel_acc_mmps) || !read(f[5], m.course_acc_mdeg)) {
    return std::nullopt;
  }
  return m;
}

bool encode(const Navacc& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin("NAVACC");
  nmea::add_optional(w, m.time);
  w.add(m.status);
  w.add_uint(m.pos_acc_mm);
  w.add_uint(m.vel_acc_mmps);
  w.add_uint(m.course_acc_mdeg);
  return w.finish(out);
}

void append_fields(const Navacc& m, frontends::FrameRecord& r) {
  using nmea::put;
  nmea::put_time(r, m.time);
  put(r, "status", m.status);
  put(r, "horizontal_pos_rms_m", m.pos_acc_mm * kMilli);
  put(r, "horizontal_vel_rms_mps", m.vel_acc_mmps * kMilli);
  put(r, "course_std_deg", m.course_acc_mdeg * kMilli);
}

}  // namespace navfuse::frontends::unicore

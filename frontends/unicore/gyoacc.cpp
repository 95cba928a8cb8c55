// GYOACC / GYOACC-V: raw (module frame) or aligned (vehicle frame) IMU and odometer pulses
// (spec L730-L801; digest §4.1-§4.2).
#include <string>

#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/sentences.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {
namespace {
constexpr std::size_t kGyoaccDataFields = 14;  // syntax L734
constexpr std::string_view kAxisNames[3] = {"x", "y", "z"};
}  // namespace

std::optional<Gyoacc> decode_gyoacc(const nmea::Fields& f, bool vehicle_frame) {
  if (f.data_count() != kGyoaccDataFields) return std::nullopt;
  Gyoacc m;
  m.vehicle_frame = vehicle_frame;
  if (!f[1].empty()) {
    m.date = nmea::parse_date_ddmmyy(f[1]);
    if (!m.date) return std::nullopt;
  }
  if (!nmea::read_optional(f[2], m.time)) return std::nullopt;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!nmea::read_optional(f[3 + i], m.gyro_rps[i]) ||
        !nmea::read_optional(f[7 + i], m.accel_mps2[i])) {
      return std::nullopt;
    }
  }
  if (!read(f[6], m.gyro_period_ms) || !read(f[10], m.accel_period_ms) ||
      !read(f[11], m.temperature_c) || !read(f[12], m.pulses) || !read(f[13], m.pulse_period_ms) ||
      !read(f[14], m.reverse)) {
    return std::nullopt;
  }
  return m;
}

bool encode(const Gyoacc& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin(m.vehicle_frame ? "GYOACC-V" : "GYOACC");
  if (m.date) nmea::add_date_ddmmyy(w, *m.date); else w.add_empty();
  nmea::add_optional(w, m.time);
  for (const auto& g : m.gyro_rps) nmea::add_optional(w, g);
  w.add_uint(m.gyro_period_ms);
  for (const auto& a : m.accel_mps2) nmea::add_optional(w, a);
  w.add_uint(m.accel_period_ms);
  w.add_int(m.temperature_c);
  w.add_uint(m.pulses);
  w.add_uint(m.pulse_period_ms);
  w.add_uint(m.reverse);
  return w.finish(out);
}

void append_fields(const Gyoacc& m, frontends::FrameRecord& r) {
  using nmea::put;
  if (m.date) {
    put(r, "utc_year", static_cast<std::int64_t>(m.date->year));
    put(r, "utc_month", static_cast<std::int64_t>(m.date->month));
    put(r, "utc_day", static_cast<std::int64_t>(m.date->day));
  } else {
    nmea::put_null(r, "utc_year");
    nmea::put_null(r, "utc_month");
    nmea::put_null(r, "utc_day");
  }
  nmea::put_time(r, m.time);
  for (std::size_t i = 0; i < 3; ++i) put(r, "gyro_" + std::string(kAxisNames[i]) + "_rps", m.gyro_rps[i]);
  put(r, "gyro_period_ms", m.gyro_period_ms);
  for (std::size_t i = 0; i < 3; ++i) put(r, "accel_" + std::string(kAxisNames[i]) + "_mps2", m.accel_mps2[i]);
  put(r, "accel_period_ms", m.accel_period_ms);
  put(r, "temperature_c", m.temperature_c);
  put(r, "odometer_pulses", m.pulses);
  put(r, "pulse_period_ms", m.pulse_period_ms);
  put(r, "reverse", m.reverse);
}

}  // namespace navfuse::frontends::unicore

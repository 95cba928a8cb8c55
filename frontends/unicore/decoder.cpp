#include "frontends/unicore/decoder.hpp"

#include <cmath>
#include <string>

#include "core/rotation/rotation.hpp"
#include "frontends/nmea/record_fields.hpp"
#include "frontends/unicore/commands_reply.hpp"
#include "frontends/unicore/to_core.hpp"

namespace navfuse::frontends::unicore {
namespace {

constexpr std::string_view kProtocol = "unicore";
constexpr double kMsToS = 1e-3;
constexpr std::size_t kLsfQueryFields = 1;  // "$LSF,system" is the query form (L1396)

char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

}  // namespace

UnicoreDecoder::UnicoreDecoder(DecoderOptions options)
    : options_(options), framer_(options.framer) {}

void UnicoreDecoder::feed(std::span<const std::uint8_t> bytes, frontends::DecodeSink& sink) {
  framer_.feed(bytes, [&](const nmea::Frame& f) { on_frame(f, sink); });
}

void UnicoreDecoder::finish(frontends::DecodeSink&) { framer_.finish(); }

bool UnicoreDecoder::fresh(const Timed& t, std::int64_t gps_ns) const {
  return t.valid && std::fabs(time::seconds(gps_ns - t.gps_ns)) <= options_.accuracy_max_age_s;
}

std::optional<std::int64_t> UnicoreDecoder::time_of_day(const std::optional<nmea::TimeOfDay>& tod) {
  if (!tod) {
    ++drops_.no_time;
    return std::nullopt;
  }
  const auto t = clock_.from_time_of_day(*tod);
  if (!t) ++drops_.no_date;
  return t;
}

template <class M>
bool UnicoreDecoder::accept(const std::optional<M>& m, const nmea::Frame& frame,
                            frontends::DecodeSink& sink) {
  if (!m) {
    ++framer_.counters().decode_errors;
    return false;
  }
  if (sink.wants_frames()) {
    frontends::FrameRecord r;
    r.protocol = kProtocol;
    r.name = std::string(fields_.name().size(), ' ');
    for (std::size_t i = 0; i < r.name.size(); ++i) r.name[i] = name_[i];
    r.offset = frame.offset;
    append_fields(*m, r);
    sink.on_frame(r);
  }
  return true;
}

void UnicoreDecoder::record_generic(const nmea::Frame& frame, frontends::DecodeSink& sink) {
  if (!sink.wants_frames()) return;
  frontends::FrameRecord r;
  r.protocol = kProtocol;
  r.name.assign(1, frame.start);
  r.name.append(name_.data(), fields_.name().size());
  r.offset = frame.offset;
  for (std::size_t i = 1; i < fields_.size(); ++i) {
    nmea::put(r, "param" + std::to_string(i), fields_[i]);
  }
  sink.on_frame(r);
}

void UnicoreDecoder::on_frame(const nmea::Frame& frame, frontends::DecodeSink& sink) {
  auto& counters = framer_.counters();
  if (!fields_.split(frame.body)) {
    ++counters.decode_errors;
    return;
  }
  const std::string_view raw = fields_.name();
  if (raw.empty() || raw.size() > name_.size()) {
    ++counters.unknown_frames;
    return;
  }
  // Names are not case-sensitive (L154): dispatch on an upper-case copy.
  for (std::size_t i = 0; i < raw.size(); ++i) name_[i] = upper(raw[i]);
  const std::string_view name(name_.data(), raw.size());
  if (frame.start == '#' || is_reply_name(name)) {  // echo, $OK/$FAIL, CFG* reports (L250-L282)
    record_generic(frame, sink);
    return;
  }
  if (name.size() == nmea::kTalkerChars + nmea::kSentenceTypeChars) {
    on_nmea(frame, name.substr(nmea::kTalkerChars), sink);
  } else {
    on_unicore(frame, name, sink);
  }
}

void UnicoreDecoder::on_nmea(const nmea::Frame& frame, std::string_view type,
                             frontends::DecodeSink& sink) {
  if (type == "GGA") {
    const auto m = nmea::decode_gga(fields_);
    if (!accept(m, frame, sink)) return;
    const auto t = time_of_day(m->time);
    if (!t) return;
    const nmea::Gst* gst = (gst_ && fresh(gst_time_, *t)) ? &*gst_ : nullptr;
    const NavSolution s = solution_from_gga(*m, *t, gst, snrstat_ ? &*snrstat_ : nullptr);
    gga_mode_ = s.mode;
    sink.on_measurement(Measurement{s});
  } else if (type == "GST") {
    const auto m = nmea::decode_gst(fields_);
    if (!accept(m, frame, sink)) return;
    if (!m->time || !clock_.has_anchor()) return;  // kept only as an accuracy for GGA
    gst_ = *m;
    gst_time_ = {*clock_.from_time_of_day(*m->time), true};
  } else if (type == "RMC") {
    const auto m = nmea::decode_rmc(fields_);
    if (!accept(m, frame, sink)) return;
    dialect_ = m->dialect;
    if (m->date && m->time) (void)clock_.from_utc(*m->date, *m->time);
  } else if (type == "ZDA") {
    const auto m = nmea::decode_zda(fields_);
    if (!accept(m, frame, sink)) return;
    if (m->time && m->day && m->month && m->year) {
      const nmea::Date d{static_cast<int>(m->year->value), static_cast<int>(m->month->value),
                         static_cast<int>(m->day->value)};
      if (time::unix_ns_from_utc(time::UtcDateTime{d.year, d.month, d.day, 0, 0, 0.0})) {
        (void)clock_.from_utc(d, *m->time);
      }
    }
  } else if (type == "GLL") {
    accept(nmea::decode_gll(fields_), frame, sink);
  } else if (type == "GSA") {
    const auto m = nmea::decode_gsa(fields_);
    if (accept(m, frame, sink)) dialect_ = m->dialect;
  } else if (type == "GSV") {
    const auto m = nmea::decode_gsv(fields_);
    if (accept(m, frame, sink)) dialect_ = m->dialect;
  } else if (type == "VTG") {
    accept(nmea::decode_vtg(fields_), frame, sink);
  } else {
    on_unicore(frame, std::string_view(name_.data(), fields_.name().size()), sink);
  }
}

void UnicoreDecoder::emit_gyoacc(const Gyoacc& m, frontends::DecodeSink& sink) {
  std::optional<std::int64_t> t;
  if (m.date && m.time) {
    t = clock_.from_utc(*m.date, *m.time);
    if (!t) ++drops_.no_date;
  } else {
    t = time_of_day(m.time);
  }
  if (!t) return;
  if (const auto imu = imu_from_gyoacc(m, *t)) {
    sink.on_measurement(Measurement{*imu});
  } else {
    ++drops_.imu_not_aligned;
  }
  // The pulses are the same in both messages: take them from the module-frame one only, so
  // that enabling both does not count them twice.
  if (m.vehicle_frame || m.pulse_period_ms == 0) return;
  cumulative_pulses_ += m.pulses;  // unsigned wrap-around is the counter's rollover
  WheelTicks ticks;
  ticks.header = {*t, TimeSource::kGps, 0, WheelTicks::kValidFrontLeft};
  ticks.ticks[0] = cumulative_pulses_;
  ticks.channels = 1;
  ticks.gear = m.reverse ? Gear::kReverse : Gear::kForward;  // "0: forward 1: reverse" (L755)
  ticks.period_s = m.pulse_period_ms * kMsToS;
  sink.on_measurement(Measurement{ticks});
  if (options_.odometer_m_per_pulse > 0.0) {
    VehicleSpeed v;
    v.header = {*t, TimeSource::kGps, 0, VehicleSpeed::kValidSpeed};
    const double speed = m.pulses * options_.odometer_m_per_pulse / ticks.period_s;
    v.speed_mps = m.reverse ? -speed : speed;
    v.is_signed = true;
    v.gear = ticks.gear;
    v.speed_std_mps = options_.odometer_speed_std_mps;
    sink.on_measurement(Measurement{v});
  }
}

void UnicoreDecoder::on_unicore(const nmea::Frame& frame, std::string_view name,
                                frontends::DecodeSink& sink) {
  // "GYOACC-V" carries a '-' (printed "GYOACC- V" with a stray space, L770; digest §11 item 14):
  // names are compared whole, never split at non-letters.
  if (name == "GYOACC" || name == "GYOACC-V") {
    const auto m = decode_gyoacc(fields_, name.size() > 6);
    if (accept(m, frame, sink)) emit_gyoacc(*m, sink);
  } else if (name == "NAVPOS") {
    const auto m = decode_navpos(fields_);
    if (!accept(m, frame, sink)) return;
    if (fix_from_quality(m->quality) == GnssFixType::kNone) {
      ++drops_.invalid_fix;
      return;
    }
    const auto t = clock_.from_ms_of_week(m->time_ms, m->system);
    if (!t) {
      ++(clock_.has_anchor() ? drops_.unsupported_time_scale : drops_.no_date);
      return;
    }
    const Navacc* acc = (navacc_ && fresh(navacc_time_, *t)) ? &*navacc_ : nullptr;
    const GnssPosition p = position_from_navpos(*m, *t, acc);
    last_lat_lon_rad_ = {p.lat_rad, p.lon_rad};
    sink.on_measurement(Measurement{p});
  } else if (name == "NAVVEL") {
    const auto m = decode_navvel(fields_);
    if (!accept(m, frame, sink)) return;
    if (fix_from_quality(m->quality) == GnssFixType::kNone) {
      ++drops_.invalid_fix;
      return;
    }
    const auto t = clock_.from_ms_of_week(m->time_ms, m->system);
    if (!t) {
      ++(clock_.has_anchor() ? drops_.unsupported_time_scale : drops_.no_date);
      return;
    }
    if (!last_lat_lon_rad_) {
      ++drops_.no_position;
      return;
    }
    const Navacc* acc = (navacc_ && fresh(navacc_time_, *t)) ? &*navacc_ : nullptr;
    sink.on_measurement(Measurement{velocity_from_navvel(*m, *t, last_lat_lon_rad_->first,
                                                         last_lat_lon_rad_->second, acc)});
  } else if (name == "NAVATT") {
    const auto m = decode_navatt(fields_);
    if (!accept(m, frame, sink)) return;
    const auto t = time_of_day(m->time);
    if (!t) return;
    sink.on_measurement(
        Measurement{solution_from_navatt(*m, *t, gga_mode_, snrstat_ ? &*snrstat_ : nullptr)});
  } else if (name == "NAVACC") {
    const auto m = decode_navacc(fields_);
    if (!accept(m, frame, sink)) return;
    if (m->status != 'A' || !m->time || !clock_.has_anchor()) return;  // 'V': invalid (L1359)
    navacc_ = *m;
    navacc_time_ = {*clock_.from_time_of_day(*m->time), true};
  } else if (name == "NAVTIME") {
    const auto m = decode_navtime(fields_);
    if (accept(m, frame, sink)) (void)clock_.on_navtime(*m);
  } else if (name == "SNRSTAT") {
    const auto m = decode_snrstat(fields_);
    if (accept(m, frame, sink)) snrstat_ = *m;
  } else if (name == "LSF") {
    if (fields_.data_count() == kLsfQueryFields) {
      record_generic(frame, sink);
      return;
    }
    const auto m = decode_lsf(fields_);
    if (accept(m, frame, sink)) clock_.on_lsf(*m);
  } else if (name == "CWOUT") {
    accept(decode_cwout(fields_), frame, sink);
  } else if (name == "NOTICE") {
    accept(decode_notice(fields_), frame, sink);
  } else if (name == "MAPFB" || name == "AIDTIME" || name == "AIDPOS") {
    record_generic(frame, sink);  // inputs, seen when a log also records the command port
  } else {
    ++framer_.counters().unknown_frames;
  }
}

}  // namespace navfuse::frontends::unicore

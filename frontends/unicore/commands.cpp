#include "frontends/unicore/commands.hpp"

#include <charconv>
#include <cmath>

#include "core/time/gps_time.hpp"
#include "frontends/nmea/latlon.hpp"
#include "frontends/nmea/utc_fields.hpp"
#include "frontends/nmea/writer.hpp"

namespace navfuse::frontends::unicore {
namespace {

constexpr std::int64_t kMsPerSecond = 1000;
constexpr double kRotatUnitsPerDeg = 100.0;   // CFGROTAT unit 0.01 deg (L542-L544)
constexpr double kRotatFullTurnUnits = 36000.0;
constexpr int kAidPosMinuteDecimals = 6;      // "4002.229934" (L662)
constexpr int kAidPosHeightDecimals = 3;      // "37.254" (L662)
constexpr int kResetMaskDigits = 2;           // "h01" (L238)
constexpr int kMapFbTimeDecimals = 3;         // hhmmss.sss (L832)
constexpr std::uint32_t kNavattRate10Hz = 10; // CFGATT freq (L726)

std::string to_text(std::uint64_t v) {
  char buf[24];
  const auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  (void)ec;
  return std::string(buf, p);
}
std::string to_text(std::int64_t v) {
  char buf[24];
  const auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  (void)ec;
  return std::string(buf, p);
}
std::string to_hex(std::uint32_t v, int min_width, char prefix) {
  char buf[16];
  const auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v, 16);
  (void)ec;
  std::string digits(buf, p);
  if (static_cast<int>(digits.size()) < min_width) digits.insert(0, static_cast<std::size_t>(min_width) - digits.size(), '0');
  return std::string(1, prefix) + digits;
}
template <class T>
std::string opt(const std::optional<T>& v) {
  if (!v) return {};
  if constexpr (std::is_signed_v<T>) {
    return to_text(static_cast<std::int64_t>(*v));
  } else {
    return to_text(static_cast<std::uint64_t>(*v));
  }
}
std::string opt_bool(const std::optional<bool>& v) { return v ? (*v ? "1" : "0") : std::string(); }

std::string finish(nmea::SentenceWriter& w) {
  std::vector<std::uint8_t> out;
  if (!w.finish(out)) return {};
  return std::string(out.begin(), out.end());
}

std::optional<std::string> rotat_angle(const std::optional<double>& deg) {
  if (!deg) return std::string();
  if (!std::isfinite(*deg)) return std::nullopt;
  double units = std::round(*deg * kRotatUnitsPerDeg);
  if (units < 0.0) units += kRotatFullTurnUnits;
  if (units < 0.0 || units > kRotatFullTurnUnits) return std::nullopt;
  return to_text(static_cast<std::uint64_t>(units));
}

}  // namespace

std::string encode_command(std::string_view name, const std::vector<std::string>& params) {
  std::size_t used = params.size();
  while (used > 0 && params[used - 1].empty()) --used;
  nmea::SentenceWriter w;
  w.begin(name);
  if (used == 0) {
    w.append(",");  // L168: a checksummed command without parameters ends its name with ','
  }
  for (std::size_t i = 0; i < used; ++i) w.add(params[i]);
  return finish(w);
}

std::string encode_query(std::string_view name) { return encode_command(name, {}); }

std::string encode(const ResetCommand& c) {
  std::optional<std::uint32_t> type;
  if (c.type) type = static_cast<std::uint32_t>(*c.type);
  return encode_command("RESET", {opt(type), c.clear_mask ? to_hex(*c.clear_mask, kResetMaskDigits, 'h') : ""});
}

std::string encode(const CfgPrtCommand& c) {
  if (!c.baud && !c.in_proto && !c.out_proto) return encode_command("CFGPRT", {opt(c.port)});
  // The second field is "reserved"/"addr", always "h0" in the examples (L301, digest §11 item 6).
  return encode_command("CFGPRT", {opt(c.port), "h0", opt(c.baud), opt(c.in_proto), opt(c.out_proto)});
}

std::string encode(const CfgMsgCommand& c) {
  return encode_command("CFGMSG", {to_text(std::uint64_t{c.message.msg_class}),
                                   to_text(std::uint64_t{c.message.msg_id}), opt_bool(c.enable)});
}

std::string encode(const CfgTpCommand& c) {
  for (const auto* d : {&c.antenna_delay_ns, &c.rf_delay_ns, &c.user_delay_ns}) {
    if (*d && (**d < INT16_MIN || **d > INT16_MAX)) return {};  // -32768~32767 ns (L398-L400)
  }
  return encode_command("CFGTP", {opt(c.interval_us), opt(c.width_us), opt(c.flags),
                                  opt(c.antenna_delay_ns), opt(c.rf_delay_ns), opt(c.user_delay_ns)});
}

std::string encode(const CfgNmeaCommand& c) {
  return encode_command("CFGNMEA", {c.version ? to_hex(*c.version, 1, 'h') : "", opt(c.ins_rate)});
}

std::string encode(const CfgSysCommand& c) {
  return encode_command("CFGSYS", {c.system_mask ? to_hex(*c.system_mask, 1, 'H') : ""});
}

std::string encode_cfgsave() { return encode_query("CFGSAVE"); }
std::string encode_cfgclr() { return encode_query("CFGCLR"); }

std::string encode(const CfgCwoutCommand& c) { return encode_command("CFGCWOUT", {opt_bool(c.enable)}); }

std::string encode(const CfgInsCommand& c) {
  return encode_command("CFGINS", {opt(c.mode), opt(c.imu_source), opt(c.odo_source), opt(c.map_source)});
}

std::string encode(const CfgRotatCommand& c) {
  const auto x = rotat_angle(c.angle_x_deg);
  const auto y = rotat_angle(c.angle_y_deg);
  const auto z = rotat_angle(c.angle_z_deg);
  if (!x || !y || !z) return {};
  return encode_command("CFGROTAT", {*x, *y, *z, opt(c.mode)});
}

std::string encode(const CfgGeoidCommand& c) { return encode_command("CFGGEOID", {opt(c.model)}); }
std::string encode(const CfgOdoFwdCommand& c) { return encode_command("CFGODOFWD", {opt(c.polarity)}); }
std::string encode(const CfgCogCommand& c) { return encode_command("CFGCOG", {opt(c.mode)}); }
std::string encode(const CfgAttCommand& c) { return encode_command("CFGATT", {opt(c.rate_hz)}); }

AidTimeCommand aid_time_from_gps_ns(std::int64_t gps_ns) {
  const std::int64_t unix_ns = time::unix_ns_from_gps_ns(gps_ns);
  const time::UtcDateTime utc = time::utc_from_unix_ns(unix_ns);
  const std::int64_t ms_of_second = (((unix_ns / 1'000'000) % kMsPerSecond) + kMsPerSecond) % kMsPerSecond;
  return {utc.year, utc.month, utc.day, utc.hour, utc.minute, static_cast<int>(utc.second),
          static_cast<int>(ms_of_second)};
}

std::string encode(const AidTimeCommand& c) {
  // Ranges of L646-L652.
  if (c.year <= 1980 || c.month < 1 || c.month > 12 || c.day < 1 || c.day > 31 || c.hour < 0 ||
      c.hour > 23 || c.minute < 0 || c.minute > 59 || c.second < 0 || c.second > 59 ||
      c.millisecond < 0 || c.millisecond > 999) {
    return {};
  }
  std::vector<std::string> p;
  for (int v : {c.year, c.month, c.day, c.hour, c.minute, c.second, c.millisecond}) {
    p.push_back(to_text(static_cast<std::uint64_t>(v)));
  }
  return encode_command("AIDTIME", p);
}

std::string encode(const AidPosCommand& c) {
  if (!std::isfinite(c.lat_deg) || !std::isfinite(c.lon_deg) || !std::isfinite(c.height_m) ||
      std::fabs(c.lat_deg) > 90.0 || std::fabs(c.lon_deg) > 180.0) {
    return {};
  }
  nmea::SentenceWriter w;
  w.begin("AIDPOS");
  nmea::add_latitude(w, {c.lat_deg, kAidPosMinuteDecimals});
  nmea::add_longitude(w, {c.lon_deg, kAidPosMinuteDecimals});
  w.add_fixed(c.height_m, kAidPosHeightDecimals);
  return finish(w);
}

std::string encode(const MapFbCommand& c) {
  if (c.utc_time_of_day_ns < 0 || c.utc_time_of_day_ns >= nmea::kNsPerDay) return {};
  nmea::SentenceWriter w;
  w.begin("MAPFB");
  nmea::add_time_of_day(w, {c.utc_time_of_day_ns, kMapFbTimeDecimals});
  for (std::int32_t v : {c.road_count, c.road_index, c.road_type, c.probability_e3, c.lat_diff_e6deg,
                         c.lon_diff_e6deg, c.up_diff_m, c.road_width_m, c.road_azimuth_e2deg}) {
    w.add_int(v);
  }
  return finish(w);
}

std::string encode_pdtinfo_query() { return encode_query("PDTINFO"); }
std::string encode_aidinfo_query() { return encode_query("AIDINFO"); }
std::string encode_lsf_query(std::uint32_t system) {
  return encode_command("LSF", {to_text(std::uint64_t{system})});
}

std::vector<std::string> fusion_setup_commands(bool save) {
  std::vector<std::string> out;
  for (const MessageId& id : {kMsgGyoacc, kMsgNavpos, kMsgNavvel, kMsgNavatt, kMsgNavacc, kMsgNavtime}) {
    out.push_back(encode(CfgMsgCommand{id, true}));
  }
  out.push_back(encode(CfgAttCommand{kNavattRate10Hz}));
  out.push_back(encode_lsf_query(0));
  if (save) out.push_back(encode_cfgsave());
  return out;
}

}  // namespace navfuse::frontends::unicore

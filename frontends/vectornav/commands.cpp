#include "frontends/vectornav/commands.hpp"

#include <charconv>
#include <cstdio>

#include "core/bytes/checks.hpp"
#include "frontends/common/device_command.hpp"
#include "frontends/vectornav/ascii_registers.hpp"
#include "frontends/vectornav/binary_layout.hpp"
#include "frontends/vectornav/float_cast.hpp"

namespace navfuse::frontends::vectornav::cmd {
namespace {

constexpr std::string_view kRead = "VNRRG";
constexpr std::string_view kWrite = "VNWRG";
constexpr std::string_view kError = "VNERR";
// Reg 51's reserved float "must stay at default" (L3736-3764).
constexpr float kVelAidControlResv = 0.01f;
constexpr std::size_t kBinaryOutputFixedFields = 2;  // AsyncMode, RateDivisor

// Shortest text that reads back as the same float (registers hold binary32 values).
std::string num(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, to_f32(v));
  return std::string(buf, r.ptr);
}

std::string hex(unsigned v, int digits) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%0*X", digits, v);
  return buf;
}

std::string body_command(std::string_view header, std::span<const std::string> values, AsciiChecksum checksum) {
  std::string body(header);
  for (const auto& v : values) body.append(",").append(v);
  return make_sentence(body, checksum);
}

std::string write_values(int id, std::initializer_list<std::string> values, AsciiChecksum checksum) {
  const std::vector<std::string> v(values);
  return write_register(id, v, checksum);
}

bool parse_double(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc{} && p == s.data() + s.size();
}

bool parse_uint(std::string_view s, int base, std::uint32_t& out) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out, base);
  return !s.empty() && ec == std::errc{} && p == s.data() + s.size();
}

template <std::size_t N>
std::optional<std::array<double, N>> parse_doubles(const Reply& r, int id) {
  if (r.kind != Reply::Kind::kRegister || r.register_id != id || r.values.size() != N) return std::nullopt;
  std::array<double, N> v{};
  for (std::size_t i = 0; i < N; ++i)
    if (!parse_double(r.values[i], v[i])) return std::nullopt;
  return v;
}

}  // namespace

std::string read_register(int id, AsciiChecksum checksum) {
  const std::string v[] = {std::to_string(id)};
  return body_command(kRead, v, checksum);
}

std::string write_register(int id, std::span<const std::string> values, AsciiChecksum checksum) {
  std::vector<std::string> all{std::to_string(id)};
  all.insert(all.end(), values.begin(), values.end());
  return body_command(kWrite, all, checksum);
}

std::string write_settings(AsciiChecksum checksum) { return make_sentence("VNWNV", checksum); }
std::string restore_factory_settings(AsciiChecksum checksum) { return make_sentence("VNRFS", checksum); }
std::string reset(AsciiChecksum checksum) { return make_sentence("VNRST", checksum); }
std::string tare(AsciiChecksum checksum) { return make_sentence("VNTAR", checksum); }
std::string async_output(bool enable, AsciiChecksum checksum) {
  return make_sentence(enable ? "VNASY,1" : "VNASY,0", checksum);
}

std::string write_binary_output(int output, const BinaryOutputConfig& config, AsciiChecksum checksum) {
  std::vector<std::string> v{std::to_string(config.async_mode), std::to_string(config.rate_divisor)};
  if (config.header.groups == 0) {
    v.push_back(hex(0, 2));
  } else {
    // The register text is the binary header, byte by byte and word by word (L5246, L5378).
    std::vector<std::uint8_t> wire;
    append_header(config.header, wire);
    std::size_t i = 0;
    for (; i < wire.size(); ++i) {
      v.push_back(hex(wire[i], 2));
      if ((wire[i] & kGroupExtensionBit) == 0) break;
    }
    for (++i; i + 1 < wire.size(); i += 2) v.push_back(hex(static_cast<unsigned>(wire[i] | (wire[i + 1] << 8)), 4));
  }
  return write_register(reg::kBinaryOutput1 + output - 1, v, checksum);
}

std::string write_reference_frame_rotation(const Eigen::Matrix3d& rfr, AsciiChecksum checksum) {
  std::vector<std::string> v;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) v.push_back(num(rfr(r, c)));  // row-major (L3480)
  return write_register(reg::kReferenceFrameRotation, v, checksum);
}

std::string write_antenna_offset(Antenna antenna, const Eigen::Vector3d& o, AsciiChecksum checksum) {
  const int id = antenna == Antenna::kInternalA ? reg::kGnssAntennaA : reg::kExternalGnssAntenna;
  return write_values(id, {num(o.x()), num(o.y()), num(o.z())}, checksum);
}

std::string write_compass_baseline(const Eigen::Vector3d& b, const Eigen::Vector3d& u, AsciiChecksum checksum) {
  return write_values(reg::kCompassBaseline, {num(b.x()), num(b.y()), num(b.z()), num(u.x()), num(u.y()), num(u.z())},
                      checksum);
}

std::string write_ins_basic_config(const InsBasicConfig& c, AsciiChecksum checksum) {
  return write_values(reg::kInsBasicConfig,
                      {std::to_string(c.scenario), c.ahrs_aiding ? "1" : "0", c.estimate_baseline ? "1" : "0", "0"},
                      checksum);
}

std::string write_velocity_aiding(const Eigen::Vector3d& v, AsciiChecksum checksum) {
  return write_values(reg::kVelAidMeasurement, {num(v.x()), num(v.y()), num(v.z())}, checksum);
}

std::string write_velocity_aiding_control(const VelocityAidingControl& c, AsciiChecksum checksum) {
  return write_values(reg::kVelAidControl, {c.enable ? "1" : "0", num(c.uncertainty_tuning), num(kVelAidControlResv)},
                      checksum);
}

BinaryOutputConfig fusion_imu_output(const FusionSetup& s) {
  BinaryOutputConfig c;
  c.async_mode = s.serial_ports;
  c.rate_divisor = static_cast<std::uint16_t>(s.imu_rate_hz > 0 ? kImuRateHz / s.imu_rate_hz : 0);
  for (unsigned t : {time_type::kTimeStartup, time_type::kTimeGps, time_type::kTimeStatus}) c.header.set(kSlotTime, t);
  for (unsigned t : {imu_type::kImuStatus, imu_type::kDeltaTheta, imu_type::kDeltaVel, imu_type::kSensSat})
    c.header.set(kSlotImu, t);
  for (unsigned t : {attitude_type::kYpr, attitude_type::kQuaternion, attitude_type::kYprU})
    c.header.set(kSlotAttitude, t);
  for (unsigned t : {ins_type::kInsStatus, ins_type::kPosLla, ins_type::kVelBody, ins_type::kVelNed, ins_type::kPosU,
                     ins_type::kVelU})
    c.header.set(kSlotIns, t);
  return c;
}

BinaryOutputConfig fusion_gnss_output(const FusionSetup& s) {
  BinaryOutputConfig c;
  c.async_mode = s.serial_ports;
  c.rate_divisor = static_cast<std::uint16_t>(s.gnss_rate_hz > 0 ? kImuRateHz / s.gnss_rate_hz : 0);
  for (std::size_t slot : {std::size_t{kSlotGnss1}, std::size_t{kSlotGnss2}})
    for (unsigned t : {gnss_type::kGpsTow, gnss_type::kGpsWeek, gnss_type::kNumSats, gnss_type::kGnssFix,
                       gnss_type::kPosLla, gnss_type::kVelNed, gnss_type::kPosUncertainty, gnss_type::kVelUncertainty,
                       gnss_type::kTimeInfo})
      c.header.set(slot, t);
  return c;
}

std::vector<std::string> fusion_setup_commands(const FusionSetup& s, AsciiChecksum checksum) {
  std::vector<std::string> out;
  out.push_back(async_output(false, checksum));
  if (s.baud_rate != 0) out.push_back(write_values(reg::kBaudRate, {std::to_string(s.baud_rate)}, checksum));
  out.push_back(write_values(reg::kAsyncType, {"0"}, checksum));
  out.push_back(write_values(reg::kDeltaConfig, {"0", "0", "0", "0", "0"}, checksum));
  out.push_back(write_values(reg::kImuFilter, {"0", "0", "0", "0", "0", "0", "0", "0", "0", "0"}, checksum));
  if (s.antenna_a_offset_m) out.push_back(write_antenna_offset(Antenna::kInternalA, *s.antenna_a_offset_m, checksum));
  if (s.compass_baseline_m) out.push_back(write_compass_baseline(*s.compass_baseline_m, s.compass_baseline_std_m, checksum));
  out.push_back(write_binary_output(1, fusion_imu_output(s), checksum));
  out.push_back(write_binary_output(2, fusion_gnss_output(s), checksum));
  if (s.save) out.push_back(write_settings(checksum));
  out.push_back(async_output(true, checksum));
  return out;
}

std::optional<Reply> parse_reply(std::string_view sentence) {
  std::string framed(sentence);
  while (!framed.empty() && (framed.back() == '\n' || framed.back() == '\r')) framed.pop_back();
  framed.append("\r\n");
  const SentenceCheck check = check_sentence(navfuse::bytes::as_bytes(framed));
  if (!check.ok || !check.body.starts_with("VN")) return std::nullopt;
  AsciiSentence s;
  if (!parse_sentence(check.body, false, s)) return std::nullopt;
  Reply r;
  r.header = std::string(s.header);
  const auto values = s.values();
  if (s.header == kError) {
    std::uint32_t code = 0;
    if (values.size() != 1 || !parse_uint(values[0], 16, code)) return std::nullopt;
    r.kind = Reply::Kind::kError;
    r.error_code = code;
    return r;
  }
  if (s.header == kRead || s.header == kWrite) {
    std::uint32_t id = 0;
    if (values.empty() || !parse_uint(values[0], 10, id)) return std::nullopt;  // errata A24: decimal
    r.kind = Reply::Kind::kRegister;
    r.register_id = static_cast<int>(id);
    for (std::size_t i = 1; i < values.size(); ++i) r.values.emplace_back(values[i]);
    return r;
  }
  r.kind = Reply::Kind::kEcho;
  for (auto v : values) r.values.emplace_back(v);
  return r;
}

std::optional<BinaryOutputConfig> parse_binary_output(const Reply& r) {
  if (r.kind != Reply::Kind::kRegister || r.register_id < reg::kBinaryOutput1 || r.register_id > reg::kBinaryOutput3 ||
      r.values.size() <= kBinaryOutputFixedFields)
    return std::nullopt;
  BinaryOutputConfig c;
  std::uint32_t mode = 0, divisor = 0;
  if (!parse_uint(r.values[0], 10, mode) || !parse_uint(r.values[1], 10, divisor) || mode > 0xFFFF ||
      divisor > 0xFFFF)
    return std::nullopt;
  c.async_mode = static_cast<std::uint16_t>(mode);
  c.rate_divisor = static_cast<std::uint16_t>(divisor);
  // Rebuild the wire header from the hex fields: group bytes, then LE type words.
  std::vector<std::uint8_t> wire;
  std::size_t i = kBinaryOutputFixedFields;
  for (; i < r.values.size(); ++i) {
    std::uint32_t g = 0;
    if (!parse_uint(r.values[i], 16, g) || g > 0xFF) return std::nullopt;
    wire.push_back(static_cast<std::uint8_t>(g));
    if ((g & kGroupExtensionBit) == 0) break;
  }
  if (wire.size() == 1 && wire[0] == 0) return i + 1 == r.values.size() ? std::optional(c) : std::nullopt;
  for (++i; i < r.values.size(); ++i) {
    std::uint32_t w = 0;
    if (!parse_uint(r.values[i], 16, w) || w > 0xFFFF) return std::nullopt;
    wire.push_back(static_cast<std::uint8_t>(w & 0xFF));
    wire.push_back(static_cast<std::uint8_t>(w >> 8));
  }
  if (parse_header(wire, c.header) != ParseStatus::kOk || c.header.header_bytes != wire.size()) return std::nullopt;
  return c;
}

std::optional<Eigen::Matrix3d> parse_reference_frame_rotation(const Reply& r) {
  const auto v = parse_doubles<9>(r, reg::kReferenceFrameRotation);
  if (!v) return std::nullopt;
  Eigen::Matrix3d m;
  for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = (*v)[static_cast<std::size_t>(k)];
  return m;
}

std::optional<Eigen::Vector3d> parse_vector3(const Reply& r, int id) {
  const auto v = parse_doubles<3>(r, id);
  if (!v) return std::nullopt;
  return Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
}

std::optional<InsBasicConfig> parse_ins_basic_config(const Reply& r) {
  const auto v = parse_doubles<4>(r, reg::kInsBasicConfig);
  if (!v || !((*v)[0] >= 0 && (*v)[0] <= 255)) return std::nullopt;  // also refuses NaN
  return InsBasicConfig{static_cast<std::uint8_t>((*v)[0]), (*v)[1] != 0, (*v)[2] != 0};
}

std::optional<VelocityAidingControl> parse_velocity_aiding_control(const Reply& r) {
  const auto v = parse_doubles<3>(r, reg::kVelAidControl);
  if (!v) return std::nullopt;
  return VelocityAidingControl{(*v)[0] != 0, to_f32((*v)[1])};
}

std::optional<CompassBaseline> parse_compass_baseline(const Reply& r) {
  const auto v = parse_doubles<6>(r, reg::kCompassBaseline);
  if (!v) return std::nullopt;
  return CompassBaseline{{(*v)[0], (*v)[1], (*v)[2]}, {(*v)[3], (*v)[4], (*v)[5]}};
}

std::string find_refusal(std::span<const std::uint8_t> reply_bytes) { return line_starting_with(reply_bytes, "$VNERR"); }

}  // namespace navfuse::frontends::vectornav::cmd

#include "frontends/vectornav/ascii_sentence.hpp"

#include <charconv>

#include "core/bytes/checks.hpp"

namespace navfuse::frontends::vectornav {
namespace {

constexpr std::size_t kXorDigits = 2;
constexpr std::size_t kCrcDigits = 4;
constexpr char kHex[] = "0123456789ABCDEF";

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

bool parse_hex(std::string_view s, std::uint32_t& v) {
  v = 0;
  if (s.empty()) return false;
  for (char c : s) {
    const int h = hex_value(c);
    if (h < 0) return false;
    v = (v << 4) | static_cast<std::uint32_t>(h);
  }
  return true;
}

bool all_x(std::string_view s) { return s.find_first_not_of('X') == std::string_view::npos; }

}  // namespace

SentenceCheck check_sentence(std::span<const std::uint8_t> frame) {
  SentenceCheck out;
  std::string_view s(reinterpret_cast<const char*>(frame.data()), frame.size());
  if (s.size() < 2 || s.front() != '$' || s.back() != '\n') return out;
  s.remove_suffix(1);
  if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
  const std::size_t star = s.rfind('*');
  if (star == std::string_view::npos || star < 1) return out;
  out.body = s.substr(1, star - 1);
  const std::string_view cs = s.substr(star + 1);
  if (cs.size() != kXorDigits && cs.size() != kCrcDigits) return out;
  out.kind = cs.size() == kXorDigits ? AsciiChecksum::kXor8 : AsciiChecksum::kCrc16;
  if (all_x(cs)) {
    out.kind = AsciiChecksum::kBypass;
    out.ok = true;
    return out;
  }
  std::uint32_t given = 0;
  if (!parse_hex(cs, given)) return out;
  const auto body = std::span<const std::uint8_t>(frame.data() + 1, out.body.size());
  const std::uint32_t computed =
      out.kind == AsciiChecksum::kXor8 ? bytes::nmea_xor(body) : bytes::crc16_xmodem(body);
  out.ok = computed == given;
  return out;
}

bool parse_sentence(std::string_view body, bool strip_appends, AsciiSentence& out) {
  out.field_count = 0;
  out.has_append_count = out.has_append_status = false;
  const std::size_t comma = body.find(',');
  out.header = body.substr(0, comma);
  if (comma == std::string_view::npos) return true;
  std::string_view rest = body.substr(comma + 1);
  while (true) {
    if (out.field_count == kMaxAsciiFields) return false;
    const std::size_t c = rest.find(',');
    out.fields[out.field_count++] = rest.substr(0, c);
    if (c == std::string_view::npos) break;
    rest.remove_prefix(c + 1);
  }
  while (strip_appends && out.field_count > 0) {
    const std::string_view f = out.fields[out.field_count - 1];
    if (f.size() > 1 && f[0] == 'T' && !out.has_append_count) {
      std::uint32_t v = 0;
      const auto [p, ec] = std::from_chars(f.data() + 1, f.data() + f.size(), v);
      if (ec != std::errc{} || p != f.data() + f.size()) break;
      out.has_append_count = true;
      out.append_count = v;
    } else if (f.size() == 1 + kCrcDigits && f[0] == 'S' && !out.has_append_status) {
      std::uint32_t v = 0;
      if (!parse_hex(f.substr(1), v)) break;
      out.has_append_status = true;
      out.append_status = static_cast<std::uint16_t>(v);
    } else {
      break;
    }
    --out.field_count;
  }
  return true;
}

std::string make_sentence(std::string_view body, AsciiChecksum kind) {
  std::string s;
  s.reserve(body.size() + 8);
  s.push_back('$');
  s.append(body);
  s.push_back('*');
  const auto bytes = bytes::as_bytes(body);
  if (kind == AsciiChecksum::kCrc16) {
    const std::uint16_t c = bytes::crc16_xmodem(bytes);
    for (int shift = 12; shift >= 0; shift -= 4) s.push_back(kHex[(c >> shift) & 0xF]);
  } else if (kind == AsciiChecksum::kXor8) {
    const std::uint8_t c = bytes::nmea_xor(bytes);
    s.push_back(kHex[c >> 4]);
    s.push_back(kHex[c & 0xF]);
  } else {
    s.append("XX");
  }
  s.append("\r\n");
  return s;
}

}  // namespace navfuse::frontends::vectornav

#include "frontends/nmea/fields.hpp"

#include <charconv>
#include <cmath>
#include <limits>

namespace navfuse::frontends::nmea {
namespace {

constexpr std::size_t kMaxHexDigits32 = 8;   // UINT hex: "a maximum of 8 characters" (L183)
constexpr std::size_t kMaxHexDigits64 = 16;  // UINT64 hex: "a maximum of 16 characters" (L190)

std::string_view trim_leading_blanks(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  return s;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

template <class T>
std::optional<T> parse_integer(std::string_view s, int base) {
  if (s.empty()) return std::nullopt;
  T value{};
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value, base);
  if (ec != std::errc{} || ptr != s.data() + s.size()) return std::nullopt;
  return value;
}

// Hex digits only: from_chars would also accept a leading '-' for signed types, and we want
// the spec's digit-count limits.
template <class T>
std::optional<T> parse_hex(std::string_view digits, std::size_t max_digits) {
  if (digits.empty() || digits.size() > max_digits || digits.front() == '-') return std::nullopt;
  return parse_integer<T>(digits, 16);
}

}  // namespace

// Fields are separated by ',' although L146 says "';' (0x2C)": 0x2C is ',' and every example
// uses it (erratum, digest §11 item 1).
bool Fields::split(std::string_view body) {
  count_ = 0;
  std::size_t begin = 0;
  while (true) {
    if (count_ == kMaxFields) return false;
    const std::size_t comma = body.find(',', begin);
    if (comma == std::string_view::npos) {
      items_[count_++] = body.substr(begin);
      return true;
    }
    items_[count_++] = body.substr(begin, comma - begin);
    begin = comma + 1;
  }
}

std::optional<double> parse_double(std::string_view field) {
  const std::string_view s = trim_leading_blanks(field);
  if (s.empty()) return std::nullopt;
  // Only the DOUBLE grammar of L192: reject "inf", "nan", exponents and '+' up front.
  bool any_digit = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (is_digit(c)) {
      any_digit = true;
    } else if (!(c == '.' || (c == '-' && i == 0))) {
      return std::nullopt;
    }
  }
  if (!any_digit) return std::nullopt;
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value, std::chars_format::fixed);
  if (ec != std::errc{} || ptr != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::int32_t> parse_int(std::string_view field) {
  const std::string_view s = trim_leading_blanks(field);
  if (s.empty() || !(is_digit(s.front()) || s.front() == '-')) return std::nullopt;
  return parse_integer<std::int32_t>(s, 10);
}

std::optional<std::uint32_t> parse_uint(std::string_view field) {
  const std::string_view s = trim_leading_blanks(field);
  if (s.empty()) return std::nullopt;
  if (s.front() == 'h' || s.front() == 'H') return parse_hex<std::uint32_t>(s.substr(1), kMaxHexDigits32);
  if (!is_digit(s.front())) return std::nullopt;
  return parse_integer<std::uint32_t>(s, 10);
}

std::optional<std::uint64_t> parse_uint64(std::string_view field) {
  const std::string_view s = trim_leading_blanks(field);
  if (s.empty()) return std::nullopt;
  if (s.front() == 'h' || s.front() == 'H') return parse_hex<std::uint64_t>(s.substr(1), kMaxHexDigits64);
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    return parse_hex<std::uint64_t>(s.substr(2), kMaxHexDigits64);
  }
  if (!is_digit(s.front())) return std::nullopt;
  return parse_integer<std::uint64_t>(s, 10);
}

std::optional<Real> parse_real(std::string_view field) {
  const std::optional<double> value = parse_double(field);
  if (!value) return std::nullopt;
  const std::string_view s = trim_leading_blanks(field);
  const std::size_t dot = s.find('.');
  const int decimals = dot == std::string_view::npos ? 0 : static_cast<int>(s.size() - dot - 1);
  return Real{*value, decimals};
}

std::optional<Count> parse_count(std::string_view field) {
  const std::string_view s = trim_leading_blanks(field);
  if (s.empty() || !is_digit(s.front())) return std::nullopt;
  const std::optional<std::uint32_t> value = parse_integer<std::uint32_t>(s, 10);
  if (!value) return std::nullopt;
  return Count{*value, static_cast<int>(s.size())};
}

std::optional<char> parse_char(std::string_view field) {
  if (field.size() != 1) return std::nullopt;
  return field.front();
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'a' && x <= 'z') x = static_cast<char>(x - 'a' + 'A');
    if (y >= 'a' && y <= 'z') y = static_cast<char>(y - 'a' + 'A');
    if (x != y) return false;
  }
  return true;
}

}  // namespace navfuse::frontends::nmea

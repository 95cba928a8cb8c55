// Field splitting and strict number parsing for the text front-ends (imutxt, rtklib) and the
// text truth references. Fields are separated by blanks (spaces, tabs: runs count once) or by a
// comma (each comma separates exactly one field, so "1,,2" has an empty middle field that fails
// to parse instead of silently shifting the columns).
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string_view>

namespace navfuse::frontends::text {

inline bool is_blank(char c) { return c == ' ' || c == '\t'; }

// Splits `line` into at most `max` fields; returns how many were found. A line with more fields
// than `max` returns max + 1 (the caller decides whether extra columns are an error).
template <std::size_t N>
std::size_t split_fields(std::string_view line, std::string_view (&out)[N]) {
  std::size_t n = 0;
  std::size_t i = 0;
  while (i < line.size() && is_blank(line[i])) ++i;
  if (i == line.size()) return 0;
  while (true) {
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i]) && line[i] != ',') ++i;
    if (n == N) return N + 1;
    out[n++] = line.substr(start, i - start);
    while (i < line.size() && is_blank(line[i])) ++i;
    if (i == line.size()) return n;
    if (line[i] == ',') {
      ++i;
      while (i < line.size() && is_blank(line[i])) ++i;
      if (i == line.size()) {  // a trailing comma leaves one empty field
        if (n == N) return N + 1;
        out[n++] = std::string_view();
        return n;
      }
    }
  }
}

// The whole field as a finite number ("+1.5", "-2e-3"); nullopt for anything else, including
// "nan" and "inf" (a damaged value, not a measurement).
inline std::optional<double> parse_number(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// A line that starts like a number ("-1.2", ".5", "2025/..."): data, as opposed to a comment or
// a column header that starts with a letter, '#', '%' or '/'.
inline bool starts_like_number(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size() && is_blank(line[i])) ++i;
  if (i == line.size()) return false;
  const char c = line[i];
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
}

inline bool is_blank_line(std::string_view line) {
  for (char c : line) {
    if (!is_blank(c)) return false;
  }
  return true;
}

}  // namespace navfuse::frontends::text

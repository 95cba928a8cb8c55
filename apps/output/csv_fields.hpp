// Locale-independent CSV fields shared by the CSV outputs (--csv, --innovations-csv): the same
// run writes the same bytes anywhere.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

namespace navfuse::apps::csv {

// ",<value>" with fixed decimals; "nan" for a non-finite value.
inline void append_fixed(std::string& row, double value, int decimals) {
  row += ',';
  if (!std::isfinite(value)) {
    row += "nan";
    return;
  }
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  row.append(buf, r.ptr);
}

// Seconds with 9 decimals from integer nanoseconds: whole seconds and nanoseconds separately,
// since a double cannot hold GPS nanoseconds exactly.
inline void append_time(std::string& row, std::int64_t time_ns) {
  char buf[40];
  std::int64_t s = time_ns / 1'000'000'000;
  std::int64_t ns = time_ns % 1'000'000'000;
  if (ns < 0) {
    ns += 1'000'000'000;
    --s;
  }
  auto r = std::to_chars(buf, buf + sizeof buf, s);
  row.append(buf, r.ptr);
  row += '.';
  char frac[9];
  for (int i = 8; i >= 0; --i, ns /= 10) frac[i] = static_cast<char>('0' + ns % 10);
  row.append(frac, 9);
}

}  // namespace navfuse::apps::csv

#include "apps/replay/truth_rows.hpp"

#include <charconv>
#include <fstream>

#include "apps/common/command_error.hpp"
#include "frontends/common/text_fields.hpp"
#include "frontends/rtklib/pos_layout.hpp"
#include "frontends/rtklib/to_core.hpp"

namespace navfuse::apps {
namespace {

namespace text = frontends::text;

// The first line of the file that is not blank.
std::string first_line(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CommandError("cannot open truth file '" + path + "'");
  std::string line;
  while (std::getline(in, line)) {
    if (!text::is_blank_line(line)) return line;
  }
  throw CommandError("truth file '" + path + "' is empty");
}

bool looks_like_nav(std::string_view line) {
  std::string_view f[16];
  const std::size_t n = text::split_fields(line, f);
  if (n != 11) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!text::parse_number(f[i])) return false;
  }
  return f[0].find('.') == std::string_view::npos;  // an integer week
}

}  // namespace

std::optional<std::int64_t> parse_time_ns(std::string_view text) {
  const auto dot = text.find('.');
  const std::string_view whole = text.substr(0, dot);
  std::int64_t s = 0;
  auto r = std::from_chars(whole.data(), whole.data() + whole.size(), s);
  if (r.ec != std::errc() || r.ptr != whole.data() + whole.size() || whole.empty() || s < 0) return std::nullopt;
  std::int64_t ns = 0;
  if (dot != std::string_view::npos) {
    const std::string_view frac = text.substr(dot + 1);
    if (frac.size() > 9) return std::nullopt;
    for (std::size_t i = 0; i < 9; ++i) {
      ns *= 10;
      if (i < frac.size()) {
        if (frac[i] < '0' || frac[i] > '9') return std::nullopt;
        ns += frac[i] - '0';
      }
    }
  }
  return s * 1'000'000'000 + ns;
}

namespace {

bool looks_like_rtklib(std::string_view line) {
  const frontends::rtklib::PosLayout layout = frontends::rtklib::default_layout(frontends::rtklib::Coordinates::kLlhDeg);
  return !line.empty() && (line.front() == '%' || frontends::rtklib::parse_record(line, layout));
}
bool looks_like_csv(std::string_view) { return true; }  // last: its reader names a missing column

// The reference formats of --truth, in detection order: the prefix that names each, a look at
// the first line that recognises it, and its reader.
struct TruthFormat {
  std::string_view prefix;
  bool (*recognises)(std::string_view first_line);
  std::unique_ptr<TruthRows> (*open)(const std::string& path);
};
constexpr TruthFormat kTruthFormats[] = {
    {"rtklib", &looks_like_rtklib, &open_rtklib_truth},
    {"nav", &looks_like_nav, &open_nav_truth},
    {"csv", &looks_like_csv, &open_csv_truth},
};

}  // namespace

std::unique_ptr<TruthRows> open_truth_rows(const std::string& argument) {
  const auto colon = argument.find(':');
  if (colon != std::string::npos) {
    const std::string_view prefix = std::string_view(argument).substr(0, colon);
    for (const TruthFormat& f : kTruthFormats) {
      if (f.prefix == prefix) return f.open(argument.substr(colon + 1));
    }
  }
  const std::string line = first_line(argument);
  for (const TruthFormat& f : kTruthFormats) {
    if (f.recognises(line)) return f.open(argument);
  }
  return open_csv_truth(argument);
}

}  // namespace navfuse::apps

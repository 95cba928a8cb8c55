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

std::unique_ptr<TruthRows> open_truth_rows(const std::string& argument) {
  const auto colon = argument.find(':');
  if (colon != std::string::npos) {
    const std::string prefix = argument.substr(0, colon);
    const std::string path = argument.substr(colon + 1);
    if (prefix == "rtklib") return open_rtklib_truth(path);
    if (prefix == "nav") return open_nav_truth(path);
    if (prefix == "csv") return open_csv_truth(path);
  }
  const std::string line = first_line(argument);
  const frontends::rtklib::PosLayout layout = frontends::rtklib::default_layout(frontends::rtklib::Coordinates::kLlhDeg);
  if (line.front() == '%' || frontends::rtklib::parse_record(line, layout)) return open_rtklib_truth(argument);
  if (looks_like_nav(line)) return open_nav_truth(argument);
  // navfuse's CSV: its own reader names the missing column when it is not one either.
  return open_csv_truth(argument);
}

}  // namespace navfuse::apps

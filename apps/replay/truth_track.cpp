#include "apps/replay/truth_track.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <string_view>

#include "apps/common/command_error.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

constexpr std::array<std::string_view, 12> kColumns = {
    "time_gps_s", "lat_deg", "lon_deg", "height_m", "vn", "ve", "vd",
    "roll_deg", "pitch_deg", "yaw_deg", "stationary", "gnss_available"};
constexpr std::size_t kRequired = 10;  // the two flags are optional

double wrap_pi(double a) { return std::remainder(a, 2.0 * rot::kPi); }

std::optional<double> parse_double(std::string_view s) {
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  return v;
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

TruthTrack::TruthTrack(const std::string& path) : path_(path), in_(path) {
  if (!in_) throw CommandError("cannot open truth file '" + path + "'");
  if (!std::getline(in_, line_)) throw CommandError("truth file '" + path + "' is empty");
  for (int& c : column_) c = -1;
  std::string_view header(line_);
  for (int col = 0; !header.empty() || col == 0; ++col) {
    const auto comma = header.find(',');
    std::string_view name = header.substr(0, comma);
    if (!name.empty() && name.back() == '\r') name.remove_suffix(1);
    for (std::size_t k = 0; k < kColumns.size(); ++k) {
      if (name == kColumns[k]) column_[k] = col;
    }
    columns_ = col + 1;
    if (comma == std::string_view::npos) break;
    header.remove_prefix(comma + 1);
  }
  for (std::size_t k = 0; k < kRequired; ++k) {
    if (column_[k] < 0) {
      throw CommandError("truth file '" + path + "' has no '" + std::string(kColumns[k]) +
                         "' column (expected the CSV written by navfuse sim --truth)");
    }
  }
}

bool TruthTrack::read_row(TruthPoint& out) {
  if (eof_ || !std::getline(in_, line_)) {
    eof_ = true;
    return false;
  }
  ++line_number_;
  std::array<std::string_view, 16> fields{};
  std::string_view rest(line_);
  if (!rest.empty() && rest.back() == '\r') rest.remove_suffix(1);
  if (rest.empty()) return read_row(out);  // tolerate blank lines
  int n = 0;
  while (n < static_cast<int>(fields.size())) {
    const auto comma = rest.find(',');
    fields[static_cast<std::size_t>(n++)] = rest.substr(0, comma);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  const auto bad = [&](std::string_view what) {
    return CommandError("truth file '" + path_ + "' line " + std::to_string(line_number_) + ": " + std::string(what));
  };
  if (n < columns_) throw bad("too few columns");
  const auto field = [&](std::size_t k) { return fields[static_cast<std::size_t>(column_[k])]; };
  const auto t = parse_time_ns(field(0));
  if (!t) throw bad("bad time_gps_s");
  std::array<double, kRequired> v{};
  for (std::size_t k = 1; k < kRequired; ++k) {
    const auto x = parse_double(field(k));
    if (!x) throw bad("bad " + std::string(kColumns[k]));
    v[k] = *x;
  }
  out.time_ns = *t;
  out.lat_rad = v[1] * rot::kDegToRad;
  out.lon_rad = v[2] * rot::kDegToRad;
  out.height_m = v[3];
  out.vel_ned_mps = {v[4], v[5], v[6]};
  out.rpy_rad = Eigen::Vector3d(v[7], v[8], v[9]) * rot::kDegToRad;
  out.stationary = column_[10] >= 0 && field(10) == "1";
  out.gnss_available = column_[11] < 0 || field(11) == "1";
  ++rows_;
  return true;
}

std::optional<TruthPoint> TruthTrack::at(std::int64_t time_ns) {
  if (!have_after_) {
    have_after_ = read_row(after_);
    if (!have_after_) return std::nullopt;
  }
  // Advance until before_ <= t <= after_.
  while (after_.time_ns < time_ns) {
    TruthPoint next;
    if (!read_row(next)) return std::nullopt;
    if (next.time_ns <= after_.time_ns) {
      throw CommandError("truth file '" + path_ + "' line " + std::to_string(line_number_) +
                         ": time does not increase");
    }
    before_ = after_;
    have_before_ = true;
    after_ = next;
  }
  if (time_ns == after_.time_ns) return after_;
  if (!have_before_ || time_ns < before_.time_ns) return std::nullopt;
  const double f = static_cast<double>(time_ns - before_.time_ns) / static_cast<double>(after_.time_ns - before_.time_ns);
  TruthPoint p = before_;
  p.time_ns = time_ns;
  p.lat_rad += f * (after_.lat_rad - before_.lat_rad);
  p.lon_rad += f * wrap_pi(after_.lon_rad - before_.lon_rad);
  p.height_m += f * (after_.height_m - before_.height_m);
  p.vel_ned_mps += f * (after_.vel_ned_mps - before_.vel_ned_mps);
  for (int i = 0; i < 3; ++i) p.rpy_rad[i] = wrap_pi(p.rpy_rad[i] + f * wrap_pi(after_.rpy_rad[i] - before_.rpy_rad[i]));
  p.stationary = before_.stationary && after_.stationary;
  p.gnss_available = before_.gnss_available && after_.gnss_available;
  return p;
}

}  // namespace navfuse::apps

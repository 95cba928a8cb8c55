// navfuse's truth CSV (apps/sim/truth_csv.hpp: time_gps_s, lat_deg, lon_deg, height_m, vn, ve,
// vd, roll_deg, pitch_deg, yaw_deg, stationary, gnss_available), columns found by name.
#include <array>

#include "apps/replay/truth_line_reader.hpp"
#include "apps/replay/truth_rows.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

constexpr std::array<std::string_view, 12> kColumns = {
    "time_gps_s", "lat_deg", "lon_deg", "height_m", "vn", "ve", "vd",
    "roll_deg", "pitch_deg", "yaw_deg", "stationary", "gnss_available"};
constexpr std::size_t kRequired = 10;  // the two flags are optional

class CsvTruthRows final : public TruthRows {
 public:
  explicit CsvTruthRows(const std::string& path) : lines_(path) {
    std::string_view header;
    if (!lines_.next(header)) throw CommandError("truth file '" + path + "' is empty");
    column_.fill(-1);
    for (int col = 0;; ++col) {
      const auto comma = header.find(',');
      const std::string_view name = header.substr(0, comma);
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
                           "' column (expected navfuse's truth CSV (navfuse sim --truth), an RTKLIB .pos "
                           "or a KF-GINS .nav; give the format as rtklib:, nav: or csv:)");
      }
    }
  }

  bool next(TruthPoint& out) override {
    std::string_view rest;
    if (!lines_.next(rest)) return false;
    std::array<std::string_view, 16> fields{};
    int n = 0;
    while (n < static_cast<int>(fields.size())) {
      const auto comma = rest.find(',');
      fields[static_cast<std::size_t>(n++)] = rest.substr(0, comma);
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
    if (n < columns_) throw lines_.error("too few columns");
    const auto field = [&](std::size_t k) { return fields[static_cast<std::size_t>(column_[k])]; };
    const auto t = parse_time_ns(field(0));
    if (!t) throw lines_.error("bad time_gps_s");
    std::array<double, kRequired> v{};
    for (std::size_t k = 1; k < kRequired; ++k) {
      const auto x = frontends::text::parse_number(field(k));
      if (!x) throw lines_.error("bad " + std::string(kColumns[k]));
      v[k] = *x;
    }
    out = TruthPoint{};
    out.time_ns = *t;
    out.lat_rad = v[1] * rot::kDegToRad;
    out.lon_rad = v[2] * rot::kDegToRad;
    out.height_m = v[3];
    out.vel_ned_mps = {v[4], v[5], v[6]};
    out.rpy_rad = Eigen::Vector3d(v[7], v[8], v[9]) * rot::kDegToRad;
    out.stationary = column_[10] >= 0 && field(10) == "1";
    out.gnss_available = column_[11] < 0 || field(11) == "1";
    return true;
  }
  std::string_view format() const override { return "csv"; }
  ReferencePoint point() const override { return ReferencePoint::kImu; }

 private:
  TruthLineReader lines_;
  std::array<int, kColumns.size()> column_{};  // file column of each field, in kColumns order
  int columns_ = 0;
};

}  // namespace

std::unique_ptr<TruthRows> open_csv_truth(const std::string& path) { return std::make_unique<CsvTruthRows>(path); }

}  // namespace navfuse::apps

// RTKLIB solutions (.pos) as a reference: read by the rtklib front-end's layout and record
// parser (frontends/rtklib), so the truth and the GNSS input agree on every form (GPST/UTC,
// deg/dms/ECEF, covariance). At the antenna; velocity when the file has the vn/ve/vu columns;
// no attitude. When the file has RTK-fixed epochs (Q=1) only those are the reference.
#include "apps/replay/truth_line_reader.hpp"
#include "apps/replay/truth_rows.hpp"
#include "frontends/rtklib/pos_layout.hpp"
#include "frontends/rtklib/to_core.hpp"

namespace navfuse::apps {
namespace {

namespace rtk = frontends::rtklib;

class RtklibTruthRows final : public TruthRows {
 public:
  explicit RtklibTruthRows(const std::string& path) : lines_(path), fixed_only_(has_fixed_epoch(path)) {}

  bool next(TruthPoint& out) override {
    std::string_view line;
    while (lines_.next(line)) {
      if (line.front() == '%') {
        rtk::read_header_line(line, layout_);
        continue;
      }
      const auto r = rtk::parse_record(line, layout_);
      if (!r) throw lines_.error("not an RTKLIB solution line");
      if (fixed_only_ && r->quality != 1) {
        ++skipped_;
        continue;
      }
      out = TruthPoint{};
      out.time_ns = r->time_ns;
      out.lat_rad = r->lat_rad;
      out.lon_rad = r->lon_rad;
      out.height_m = r->height_m;
      out.has_velocity = r->has_velocity;
      out.vel_ned_mps = r->vel_ned_mps;
      out.has_attitude = false;
      return true;
    }
    return false;
  }
  std::string_view format() const override { return "rtklib"; }
  ReferencePoint point() const override { return ReferencePoint::kAntenna; }
  bool sparse() const override { return true; }
  std::uint64_t rows_skipped() const override { return skipped_; }

 private:
  // A first pass over the file, up to its first fixed epoch.
  static bool has_fixed_epoch(const std::string& path) {
    TruthLineReader lines(path);
    rtk::PosLayout layout = rtk::default_layout(rtk::Coordinates::kLlhDeg);
    std::string_view line;
    while (lines.next(line)) {
      if (line.front() == '%') {
        rtk::read_header_line(line, layout);
      } else if (const auto r = rtk::parse_record(line, layout); r && r->quality == 1) {
        return true;
      }
    }
    return false;
  }

  TruthLineReader lines_;
  rtk::PosLayout layout_ = rtk::default_layout(rtk::Coordinates::kLlhDeg);
  bool fixed_only_;
  std::uint64_t skipped_ = 0;
};

}  // namespace

std::unique_ptr<TruthRows> open_rtklib_truth(const std::string& path) {
  return std::make_unique<RtklibTruthRows>(path);
}

}  // namespace navfuse::apps

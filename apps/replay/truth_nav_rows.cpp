// KF-GINS / i2Nav reference trajectories (.nav): per line GPS week, seconds of week, latitude and
// longitude (deg), ellipsoidal height (m), velocity north/east/down (m/s), roll, pitch, yaw (deg)
// (the truth.nav of the KF-GINS data sets; the navigation result KF-GINS writes has the same
// columns). Positions are at the IMU.
#include "apps/replay/truth_line_reader.hpp"
#include "apps/replay/truth_rows.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::apps {
namespace {

constexpr std::size_t kColumns = 11;

class NavTruthRows final : public TruthRows {
 public:
  explicit NavTruthRows(const std::string& path) : lines_(path) {}

  bool next(TruthPoint& out) override {
    std::string_view line;
    if (!lines_.next(line)) return false;
    std::string_view f[kColumns + 1];
    if (frontends::text::split_fields(line, f) != kColumns) throw lines_.error("expected 11 columns");
    double v[kColumns] = {};
    for (std::size_t i = 0; i < kColumns; ++i) {
      const auto x = frontends::text::parse_number(f[i]);
      if (!x) throw lines_.error("not a number: '" + std::string(f[i]) + "'");
      v[i] = *x;
    }
    if (v[0] < 0 || v[0] != static_cast<double>(static_cast<std::int32_t>(v[0])) || v[1] < 0 ||
        v[1] >= static_cast<double>(time::kSecondsPerWeek)) {
      throw lines_.error("bad GPS week / seconds of week");
    }
    out = TruthPoint{};
    out.time_ns = time::gps_ns_from_week_tow(static_cast<std::int32_t>(v[0]), v[1]);
    out.lat_rad = v[2] * rot::kDegToRad;
    out.lon_rad = v[3] * rot::kDegToRad;
    out.height_m = v[4];
    out.vel_ned_mps = {v[5], v[6], v[7]};
    out.rpy_rad = Eigen::Vector3d(v[8], v[9], v[10]) * rot::kDegToRad;
    return true;
  }
  std::string_view format() const override { return "nav"; }
  ReferencePoint point() const override { return ReferencePoint::kImu; }

 private:
  TruthLineReader lines_;
};

}  // namespace

std::unique_ptr<TruthRows> open_nav_truth(const std::string& path) { return std::make_unique<NavTruthRows>(path); }

}  // namespace navfuse::apps

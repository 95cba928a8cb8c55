// The rows of a reference trajectory (`--truth` of replay and bench), whatever its file format:
//   csv     navfuse's own truth CSV (navfuse sim --truth; truth_csv_rows.cpp), at the IMU point;
//   rtklib  an RTKLIB solution (.pos; frontends/rtklib), at the GNSS antenna, position (and
//           velocity when the file has it) only; when the file has RTK-fixed epochs only those
//           are the reference (float and single solutions are metres, not centimetres, off);
//   nav     a KF-GINS / i2Nav reference (.nav: week, seconds of week, lat, lon, height (deg, m),
//           vN vE vD (m/s), roll pitch yaw (deg); truth_nav_rows.cpp), at the IMU point.
// The format is given as a prefix ("rtklib:PATH", "nav:PATH", "csv:PATH") or detected from the
// first line that is not blank: '%' or an RTKLIB solution line -> rtklib; a header naming
// time_gps_s -> csv; 11 numbers starting with an integer week -> nav.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

struct TruthPoint {
  std::int64_t time_ns = 0;  // GPS time
  double lat_rad = 0.0, lon_rad = 0.0, height_m = 0.0;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();
  bool has_velocity = true;
  bool has_attitude = true;
  bool stationary = false;
  bool gnss_available = true;
};

// Where on the vehicle the reference's positions are.
enum class ReferencePoint : std::uint8_t { kImu, kAntenna };

class TruthRows {
 public:
  virtual ~TruthRows() = default;
  // The next row; false at the end. Throws CommandError naming the file and line on a row that
  // does not read.
  virtual bool next(TruthPoint& out) = 0;
  virtual std::string_view format() const = 0;
  virtual ReferencePoint point() const = 0;
  // True when the rows are sparse against the pose rate (a 1-10 Hz GNSS solution): compared at
  // the reference's own epochs, with the poses interpolated, rather than the reference
  // interpolated at every pose.
  virtual bool sparse() const { return false; }
  // Rows read but not used as reference (RTKLIB epochs that are not RTK-fixed).
  virtual std::uint64_t rows_skipped() const { return 0; }
};

// Opens "[rtklib:|nav:|csv:]PATH"; throws CommandError naming the file when it cannot be opened
// or is not a reference of a known format.
std::unique_ptr<TruthRows> open_truth_rows(const std::string& argument);

// The format-specific openers (used by open_truth_rows and tests).
std::unique_ptr<TruthRows> open_csv_truth(const std::string& path);
std::unique_ptr<TruthRows> open_rtklib_truth(const std::string& path);
std::unique_ptr<TruthRows> open_nav_truth(const std::string& path);

// Parses "seconds.fraction" into integer nanoseconds exactly (a double cannot hold GPS ns).
std::optional<std::int64_t> parse_time_ns(std::string_view text);

}  // namespace navfuse::apps

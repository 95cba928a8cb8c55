// Reads the simulator's truth CSV (apps/sim/truth_csv.hpp: time_gps_s, lat_deg, lon_deg,
// height_m, vn, ve, vd, roll_deg, pitch_deg, yaw_deg, stationary, gnss_available) as a stream
// and interpolates it at increasing query times, keeping only the two rows that bracket the
// query: memory stays constant however long the drive.
//
// Interpolation is linear in time for position, velocity and roll/pitch, and linear along the
// shorter arc for yaw. Truth is written at the IMU rate (200 Hz in the scenarios), where the
// linearisation error is far below the errors being measured (20 m/s * 5 ms = 0.1 m of travel
// per interval, interpolated to well under a millimetre on a straight or gently curving road).
#pragma once

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>

#include <Eigen/Core>

namespace navfuse::apps {

struct TruthPoint {
  std::int64_t time_ns = 0;  // GPS time
  double lat_rad = 0.0, lon_rad = 0.0, height_m = 0.0;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();
  bool stationary = false;
  bool gnss_available = true;
};

class TruthTrack {
 public:
  // Opens the file and reads its header; throws CommandError naming the file and the problem
  // (missing, not a truth CSV: a required column is absent).
  explicit TruthTrack(const std::string& path);

  // Truth at `time_ns`; nullopt outside the file's time span. Query times must not decrease
  // (earlier times than a previous query return nullopt). Throws CommandError on a malformed row.
  std::optional<TruthPoint> at(std::int64_t time_ns);

  std::uint64_t rows_read() const { return rows_; }

 private:
  bool read_row(TruthPoint& out);

  std::string path_;
  std::ifstream in_;
  std::string line_;
  int column_[12];  // file column of each required field, in TruthPoint order
  int columns_ = 0;
  TruthPoint before_, after_;
  bool have_before_ = false, have_after_ = false, eof_ = false;
  std::uint64_t rows_ = 0;
  std::uint64_t line_number_ = 1;
};

// Parses "seconds.fraction" into integer nanoseconds exactly (a double cannot hold GPS ns).
std::optional<std::int64_t> parse_time_ns(std::string_view text);

}  // namespace navfuse::apps

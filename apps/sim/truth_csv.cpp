// Truth CSV writer (columns documented in truth_csv.hpp).
#include "apps/sim/truth_csv.hpp"

#include <cinttypes>
#include <algorithm>
#include <cstdio>
#include <fstream>

#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::sim {

TruthCsvWriter::TruthCsvWriter(std::ostream& out) : out_(out) {
  out_ << "time_gps_s,lat_deg,lon_deg,height_m,vn,ve,vd,roll_deg,pitch_deg,yaw_deg,stationary,"
          "gnss_available\n";
}

void TruthCsvWriter::write(const TruthSample& s) {
  // snprintf, not iostream formatting: fixed decimals independent of the stream's locale/flags,
  // and the time printed from integer ns so that it is exact.
  const std::int64_t sec = s.time_ns / time::kNsPerSecond;
  const std::int64_t frac = s.time_ns % time::kNsPerSecond;
  // Adding +0.0 turns a negative zero (e.g. -sin(pitch) * 0 m/s) into +0, so rest prints "0.0".
  const Eigen::Vector3d rpy = s.rpy_rad * rot::kRadToDeg + Eigen::Vector3d::Zero();
  const Eigen::Vector3d v = s.vel_ned_mps + Eigen::Vector3d::Zero();
  char line[320];
  const int n = std::snprintf(
      line, sizeof line,
      "%" PRId64 ".%09" PRId64 ",%.10f,%.10f,%.4f,%.5f,%.5f,%.5f,%.6f,%.6f,%.6f,%d,%d\n", sec, frac,
      s.llh.lat_rad * rot::kRadToDeg, s.llh.lon_rad * rot::kRadToDeg, s.llh.height_m,
      v.x(), v.y(), v.z(), rpy.x(), rpy.y(), rpy.z(),
      s.stationary ? 1 : 0, s.gnss_available ? 1 : 0);
  if (n > 0) out_.write(line, std::min<std::streamsize>(n, static_cast<std::streamsize>(sizeof line) - 1));
}

void write_truth_csv(std::ostream& out, const std::vector<TruthSample>& truth) {
  TruthCsvWriter w(out);
  for (const TruthSample& s : truth) w.write(s);
}

bool write_truth_csv_file(const std::string& path, const std::vector<TruthSample>& truth,
                          std::string* error) {
  std::ofstream f(path, std::ios::binary);
  if (!f) {
    if (error) *error = "cannot open " + path + " for writing";
    return false;
  }
  write_truth_csv(f, truth);
  f.flush();
  if (!f) {
    if (error) *error = "write to " + path + " failed";
    return false;
  }
  return true;
}

}  // namespace navfuse::sim

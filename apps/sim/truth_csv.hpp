// Truth as CSV, for plots and for `navfuse bench` comparisons against truth.
//
// Columns (header row first, one row per TruthSample, '.' decimal point, no thousands separator):
//   time_gps_s       GPS time, seconds since 1980-01-06 (9 decimals: exact to the ns)
//   lat_deg, lon_deg geodetic WGS-84 latitude/longitude of the vehicle reference point (10 decimals)
//   height_m         height above the WGS-84 ellipsoid (4 decimals)
//   vn, ve, vd       velocity in NED, m/s (5 decimals)
//   roll_deg, pitch_deg, yaw_deg   attitude of the vehicle FRD frame, 3-2-1 Euler, yaw in
//                    [-180, 180) (6 decimals)
//   stationary       1 when exactly at rest, else 0
//   gnss_available   1 when a GNSS fix would be produced (not in an outage), else 0
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "apps/sim/trajectory.hpp"

namespace navfuse::sim {

class TruthCsvWriter {
 public:
  explicit TruthCsvWriter(std::ostream& out);  // writes the header row
  void write(const TruthSample& s);

 private:
  std::ostream& out_;
};

void write_truth_csv(std::ostream& out, const std::vector<TruthSample>& truth);
// Returns false (and fills `error`) when the file cannot be written.
bool write_truth_csv_file(const std::string& path, const std::vector<TruthSample>& truth,
                          std::string* error = nullptr);

}  // namespace navfuse::sim

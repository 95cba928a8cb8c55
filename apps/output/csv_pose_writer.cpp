#include "apps/output/csv_pose_writer.hpp"

#include <cmath>

#include "apps/common/calibration_groups.hpp"
#include "apps/output/csv_fields.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

constexpr const char* kPoseHeader =
    "time_s,time_source,mode,lat_deg,lon_deg,height_m,vn_mps,ve_mps,vd_mps,roll_deg,pitch_deg,yaw_deg,"
    "pos_std_n_m,pos_std_e_m,pos_std_d_m,vel_std_n_mps,vel_std_e_mps,vel_std_d_mps,roll_std_deg,"
    "pitch_std_deg,yaw_std_deg";

// The pose columns, then the calibration columns (appended, so readers of the pose columns by
// position keep working): per group its values, then its std devs.
std::string header() {
  std::string h = kPoseHeader;
  for (const CalibrationGroup& g : calibration_groups(NavSolution{})) {
    for (bool is_std : {false, true}) {
      for (int i = 0; i < g.count; ++i) h += ',' + g.column(i, is_std);
    }
  }
  return h + '\n';
}

using csv::append_fixed;
using csv::append_time;

}  // namespace

CsvPoseWriter::CsvPoseWriter(const std::string& path) : file_(path) {
  file_.write(header());
  row_.reserve(512);
}

void CsvPoseWriter::write(const OutputEpoch& epoch) {
  if (!epoch.pose_due) return;
  const NavSolution& s = epoch.solution;
  constexpr double d = rot::kRadToDeg;
  row_.clear();
  append_time(row_, s.header.time_ns);
  row_ += ',';
  row_ += to_string(s.header.time_source);
  row_ += ',';
  row_ += to_string(s.mode);
  // What the solution does not have is written as "nan" (the FusionEngine Pose convention).
  const auto valid = [&](std::uint32_t bit) { return (s.header.valid & bit) != 0; };
  const auto put = [&](double value, int decimals, std::uint32_t bit) {
    append_fixed(row_, valid(bit) ? value : std::nan(""), decimals);
  };
  put(s.lat_rad * d, 10, NavSolution::kValidPosition);
  put(s.lon_rad * d, 10, NavSolution::kValidPosition);
  put(s.height_m, 4, NavSolution::kValidPosition);
  for (int i = 0; i < 3; ++i) put(s.vel_ned_mps[i], 5, NavSolution::kValidVelocity);
  for (int i = 0; i < 2; ++i) put(s.rpy_rad[i] * d, 6, NavSolution::kValidAttitude);
  put(s.rpy_rad[2] * d, 6, valid(NavSolution::kValidAttitude) ? NavSolution::kValidHeading : 0u);
  for (int i = 0; i < 3; ++i) put(s.pos_std_ned_m[i], 4, NavSolution::kValidPositionStd);
  for (int i = 0; i < 3; ++i) put(s.vel_std_ned_mps[i], 5, NavSolution::kValidVelocityStd);
  for (int i = 0; i < 3; ++i) put(s.att_std_rpy_rad[i] * d, 6, NavSolution::kValidAttitudeStd);
  for (const CalibrationGroup& g : calibration_groups(s)) {
    for (const auto* column : {&g.value, &g.std}) {
      for (int i = 0; i < g.count; ++i) {
        append_fixed(row_, g.estimated ? (*column)[static_cast<std::size_t>(i)] : std::nan(""), g.decimals);
      }
    }
  }
  row_ += '\n';
  file_.write(row_);
}

}  // namespace navfuse::apps

#include "filter/control/baseline_check.hpp"

#include <cmath>

#include "core/rotation/rotation.hpp"

namespace navfuse::filter {
namespace {

// Course and antenna yaw further apart than this disagree: sideslip of a car stays below ~5 deg
// and a noisy course is refused by kinematic_max_course_std_rad, so 30 deg is no normal driving;
// a wrong baseline is off by its own error (180 deg for swapped antennas).
constexpr double kMismatch_rad = 30.0 * rot::kDegToRad;
// Consecutive disagreeing epochs before the offset is flagged (2 s at 5 Hz): a short reverse
// manoeuvre, the one normal case of course and yaw 180 deg apart, is rarely this long above the
// alignment speed, and a reverse gear reported by odometry stops the count.
constexpr int kMismatchesToFlag = 10;
// The antenna yaw compared must be this recent.
constexpr double kMaxYawAge_s = 1.0;

}  // namespace

void note_antenna_yaw(FilterCore& c, std::int64_t time_ns, double vehicle_yaw_rad) {
  c.gnss.baseline.antenna_yaw_rad = vehicle_yaw_rad;
  c.gnss.baseline.antenna_yaw_ns = time_ns;
}

bool check_baseline(FilterCore& c, const FilterOptions& o, const GnssVelocity& m, double course_std_rad) {
  BaselineCheckState& b = c.gnss.baseline;
  // Course and yaw agree only where the course is a heading (course_alignment: a land vehicle).
  if (b.offset_detected || !o.course_alignment) return false;
  const double speed = m.vel_ned_mps.head<2>().norm();
  const bool reversing = c.odometry.last_speed_mps < 0.0 &&
                         seconds_since(m.header.time_ns, c.odometry.last_speed_ns) < kMaxYawAge_s;
  if (speed < o.kinematic_alignment_speed_mps || course_std_rad > o.kinematic_max_course_std_rad || reversing ||
      std::abs(seconds_since(m.header.time_ns, b.antenna_yaw_ns)) > kMaxYawAge_s) {
    return false;
  }
  const double course = std::atan2(m.vel_ned_mps.y(), m.vel_ned_mps.x());
  const double offset = rot::wrap_pi(b.antenna_yaw_rad - course);
  if (std::abs(offset) <= kMismatch_rad) {
    b.mismatches = 0;
    return false;
  }
  if (++b.mismatches < kMismatchesToFlag) return false;
  b.offset_detected = true;
  b.offset_rad = offset;
  return true;
}

}  // namespace navfuse::filter

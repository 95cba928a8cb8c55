#include "apps/replay/truth_track.hpp"

#include <cmath>

#include "apps/common/command_error.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

double wrap_pi(double a) { return std::remainder(a, 2.0 * rot::kPi); }

}  // namespace

TruthTrack::TruthTrack(const std::string& argument) : rows_source_(open_truth_rows(argument)) {}

bool TruthTrack::read_row(TruthPoint& out) {
  if (eof_ || !rows_source_->next(out)) {
    eof_ = true;
    return false;
  }
  if (rows_ > 0 && out.time_ns <= last_time_ns_) {
    throw CommandError("truth file: row " + std::to_string(rows_ + 1) + " (" + std::string(format()) +
                       "): time does not increase");
  }
  ++rows_;
  last_time_ns_ = out.time_ns;
  return true;
}

std::optional<TruthPoint> TruthTrack::next_until(std::int64_t time_ns) {
  if (!have_after_) {
    have_after_ = read_row(after_);
    if (!have_after_) return std::nullopt;
  }
  if (after_.time_ns > time_ns) return std::nullopt;
  const TruthPoint row = after_;
  have_after_ = false;
  return row;
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
  p.has_velocity = before_.has_velocity && after_.has_velocity;
  p.has_attitude = before_.has_attitude && after_.has_attitude;
  p.stationary = before_.stationary && after_.stationary;
  p.gnss_available = before_.gnss_available && after_.gnss_available;
  return p;
}

}  // namespace navfuse::apps

// A navigation solution over time, as `navfuse bench` keeps it: navfuse's poses, the device's own
// solutions decoded from the log, or truth. Only the fields the comparison and the report use are
// kept (about 190 bytes a sample instead of a whole NavSolution), so an hour at 100 Hz stays
// around 70 MB.
//
// Devices often report position, velocity and attitude in separate messages (UM220 NAVPOS /
// NAVVEL / NAVATT, a VN-300 Attitude group without the INS group), each a partial NavSolution
// whose header.valid bits say which parts it carries. Each quantity is therefore compared on its
// own: a sample takes part in the position comparison only when it has a valid position, and so
// on (see Quantity and has()).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"

namespace navfuse::apps::bench {

struct TrackSample {
  std::int64_t time_ns = 0;
  NavMode mode = NavMode::kInvalid;
  std::uint32_t valid = 0;         // NavSolution::kValid* bits
  std::uint32_t status_flags = 0;  // NavSolution::kStatus* bits
  double lat_rad = 0.0, lon_rad = 0.0, height_m = 0.0;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();
  // 1-sigma uncertainties the solution reports about itself (valid with the kValid*Std bits).
  Eigen::Vector3d pos_std_ned_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d vel_std_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d att_std_rpy_rad = Eigen::Vector3d::Zero();
};

TrackSample track_sample_from(const NavSolution& s);

// The parts of a solution compared separately. kHeading is split from kAttitude because a
// levelled solution (vertical gyro, UM220 NAVATT before heading is known) has roll and pitch
// without a meaningful yaw.
enum class Quantity : std::uint8_t { kPosition = 0, kVelocity, kAttitude, kHeading, kCount };
inline constexpr std::size_t kQuantityCount = static_cast<std::size_t>(Quantity::kCount);
std::string_view to_string(Quantity q);

// True when `s` carries quantity `q` (its validity bit is set).
bool has(const TrackSample& s, Quantity q);
// True when `s` carries the 1-sigma uncertainty of `q`.
bool has_std(const TrackSample& s, Quantity q);

// A full navigation solution (position, velocity and attitude all estimated): the modes in which
// navfuse's poses are judged, the same set `navfuse replay --truth` uses.
inline bool is_navigating(NavMode m) {
  return m == NavMode::kNavigation || m == NavMode::kDeadReckoning || m == NavMode::kSmoothed;
}

// Samples in strictly increasing time order, which interpolation needs. A partial solution with
// the same time as the last sample is merged into it (UM220 NAVPOS, NAVVEL and NAVATT of one
// epoch become one sample); one before the last sample (a device reordering epochs) is dropped
// and counted.
class SolutionTrack {
 public:
  // False (and nothing stored) when `s` is before the last sample.
  bool append(const TrackSample& s);
  const std::vector<TrackSample>& samples() const { return samples_; }
  bool empty() const { return samples_.empty(); }
  std::size_t size() const { return samples_.size(); }
  std::uint64_t dropped() const { return dropped_; }

  // The samples that carry `q`, optionally only those in a navigating mode (see is_navigating),
  // as pointers into this track (valid until the next append).
  std::vector<const TrackSample*> with(Quantity q, bool navigating_only) const;
  // The samples that carry at least one quantity.
  std::vector<const TrackSample*> with_any() const;

 private:
  std::vector<TrackSample> samples_;
  std::uint64_t dropped_ = 0;
};

}  // namespace navfuse::apps::bench

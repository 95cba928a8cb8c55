// A navigation solution over time, as `navfuse bench` keeps it: navfuse's poses, the device's own
// solutions decoded from the log, or truth. Only the fields the comparison and the report use are
// kept (about 180 bytes a sample instead of a whole NavSolution), and they are kept on disk
// (apps/common/spill_file.hpp: an anonymous temporary file, about 65 MB per hour at 100 Hz), so
// bench's memory does not grow with the log: tracks are read back in time order by readers and
// filtered views (TrackView), one pass at a time.
//
// Devices often report position, velocity and attitude in separate messages (UM220 NAVPOS /
// NAVVEL / NAVATT, a VN-300 Attitude group without the INS group), each a partial NavSolution
// whose header.valid bits say which parts it carries. Each quantity is therefore compared on its
// own: a sample takes part in the position comparison only when it has a valid position, and so
// on (see Quantity and has()).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "apps/common/spill_file.hpp"
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

}  // namespace navfuse::apps::bench

// A TrackSample is plain values (Eigen fixed-size vectors are arrays of doubles): spilled as bytes.
template <>
inline constexpr bool navfuse::apps::kSpillableAsBytes<navfuse::apps::bench::TrackSample> = true;

namespace navfuse::apps::bench {

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

class TrackView;

// Samples in strictly increasing time order, which interpolation needs. A partial solution with
// the same time as the last sample is merged into it (UM220 NAVPOS, NAVVEL and NAVATT of one
// epoch become one sample); one before the last sample (a device reordering epochs) is dropped
// and counted.
class SolutionTrack {
 public:
  using Reader = SpillFile<TrackSample>::Reader;

  // False (and nothing stored) when `s` is before the last sample.
  bool append(const TrackSample& s);
  // Every sample in time order (the track must outlive the reader).
  Reader reader() const { return samples_.reader(); }
  bool empty() const { return samples_.empty(); }
  std::size_t size() const { return samples_.size(); }
  std::uint64_t dropped() const { return dropped_; }

  // The samples that carry `q`, optionally only those in a navigating mode (see is_navigating).
  TrackView with(Quantity q, bool navigating_only) const;
  // The samples that carry at least one quantity.
  TrackView with_any() const;

 private:
  SpillFile<TrackSample> samples_{1024};
  std::uint64_t dropped_ = 0;
};

// Which samples of a track a comparison uses.
struct TrackFilter {
  std::optional<Quantity> quantity;  // nullopt: at least one quantity
  bool navigating_only = false;      // is_navigating(mode)
  bool estimating_only = false;      // mode past kInitializing (a device's fields hold estimates)

  bool matches(const TrackSample& s) const;
};

// The samples of a track that pass a filter, read in time order. The count and the first and last
// times take one pass, made when first asked; the track must outlive the view and its readers.
class TrackView {
 public:
  TrackView(const SolutionTrack& track, TrackFilter filter) : track_(&track), filter_(filter) {}

  class Reader {
   public:
    bool next(TrackSample& out);

   private:
    friend class TrackView;
    Reader(SolutionTrack::Reader reader, TrackFilter filter) : reader_(std::move(reader)), filter_(filter) {}
    SolutionTrack::Reader reader_;
    TrackFilter filter_;
  };
  Reader reader() const { return Reader(track_->reader(), filter_); }

  bool empty() const { return extent().size == 0; }
  std::size_t size() const { return extent().size; }
  std::int64_t first_ns() const { return extent().first_ns; }  // 0 when empty
  std::int64_t last_ns() const { return extent().last_ns; }
  // The first sample (nullopt when empty).
  std::optional<TrackSample> front() const;

 private:
  struct Extent {
    std::size_t size = 0;
    std::int64_t first_ns = 0, last_ns = 0;
  };
  const Extent& extent() const;

  const SolutionTrack* track_;
  TrackFilter filter_;
  mutable std::optional<Extent> extent_;
};

}  // namespace navfuse::apps::bench
